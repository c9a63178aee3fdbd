package gizmoball.headless;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import java.nio.file.Path;
import java.util.List;
import java.util.Optional;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;

class HeadlessOptionsTest {

    @Test
    void readsEveryOptionInAnyOrder() throws HeadlessOptions.BadArguments {
        HeadlessOptions options = HeadlessOptions.parse(List.of(
                "--out", "after.txt", "board.txt", "--skip-bad-lines", "--dt", "0.01", "--headless", "--ticks", "2000"));
        assertThat(options).isEqualTo(new HeadlessOptions.Play(Path.of("board.txt"), 2000, Optional.of(0.01), true,
                Optional.of(Path.of("after.txt")), Optional.empty(), Optional.empty(), Optional.empty(), 1));
    }

    @Test
    void onlyTicksAndBoardAreRequired() throws HeadlessOptions.BadArguments {
        assertThat(HeadlessOptions.parse(List.of("--headless", "--ticks", "0", "b.txt"))).isEqualTo(
                new HeadlessOptions.Play(Path.of("b.txt"), 0, Optional.empty(), false, Optional.empty(),
                        Optional.empty(), Optional.empty(), Optional.empty(), 1));
    }

    @Test
    void readsTheGameOptions() throws HeadlessOptions.BadArguments {
        assertThat(HeadlessOptions.parse(List.of("--headless", "--keys", "k.txt", "--ticks", "9", "--record", "r.json",
                "--report", "s.json", "--players", "3", "b.txt"))).isEqualTo(new HeadlessOptions.Play(Path.of("b.txt"), 9,
                Optional.empty(), false, Optional.empty(), Optional.of(Path.of("k.txt")), Optional.of(Path.of("s.json")),
                Optional.of(Path.of("r.json")), 3));
        assertThatThrownBy(() -> HeadlessOptions.parse(List.of("--ticks", "9", "--players", "5", "b.txt")))
                .hasMessageContaining("--players needs 1 to 4, not 5");
        assertThat(HeadlessOptions.parse(List.of("--replay", "r.json", "--headless", "--report", "s.json")))
                .isEqualTo(new HeadlessOptions.Check(Path.of("r.json"), Optional.of(Path.of("s.json"))));
    }

    @Test
    void readsTheLabsOptions() throws HeadlessOptions.BadArguments {
        assertThat(HeadlessOptions.parse(List.of("--headless", "--lab", "200", "--threads", "2", "--game-cap", "90",
                "--report", "lab.json", "--heatmap", "lab.png", "b.txt"))).isEqualTo(new HeadlessOptions.Lab(
                Path.of("b.txt"), 200, 2, 90.0, false, Optional.of(Path.of("lab.json")), Optional.of(Path.of("lab.png"))));
        HeadlessOptions.Lab lab = (HeadlessOptions.Lab) HeadlessOptions.parse(List.of("--lab", "5", "b.txt"));
        assertThat(lab.threads()).isEqualTo(Runtime.getRuntime().availableProcessors());
        assertThat(lab.gameCapSeconds()).isEqualTo(600.0);
    }

    @ParameterizedTest(name = "{0}")
    @CsvSource(delimiter = '|', value = {
            "--headless b.txt | --ticks N is required",
            "--headless --ticks 5 | no board file given",
            "--headless --ticks | --ticks needs a value",
            "--headless --ticks -1 b.txt | --ticks needs a whole number >= 0, not '-1'",
            "--headless --ticks ten b.txt | --ticks needs a whole number >= 0, not 'ten'",
            "--headless --ticks 5 --dt 0 b.txt | --dt needs a number of seconds > 0, not '0'",
            "--headless --ticks 5 --dt NaN b.txt | --dt needs a number of seconds > 0, not 'NaN'",
            "--headless --ticks 5 --fast b.txt | unknown option --fast",
            "--headless --ticks 5 -x b.txt | unknown option -x",
            "--headless --ticks 5 a.txt b.txt | more than one board file: a.txt and b.txt",
            "--headless --ticks 5 b.txt --out | --out needs a value",
            "--headless --ticks 5 --keys | --keys needs a value",
            "--headless --replay r.json b.txt | --replay takes only --report: the replay file holds the board, its ticks, keys and players",
            "--headless --replay r.json --ticks 5 | --replay takes only --report: the replay file holds the board, its ticks, keys and players",
            "--headless --lab 0 b.txt | --lab needs a whole number >= 1, not '0'",
            "--headless --lab many b.txt | --lab needs a whole number >= 1, not 'many'",
            "--headless --lab 5 --threads 0 b.txt | --threads needs a whole number >= 1, not '0'",
            "--headless --lab 5 --game-cap -3 b.txt | --game-cap needs a number of seconds > 0, not '-3'",
            "--headless --lab 5 | no board file given",
            "--headless --lab | --lab needs a value",
            "--headless --ticks 5 --threads 2 b.txt | --threads goes with --lab N",
            "--headless --ticks 5 --game-cap 60 b.txt | --game-cap goes with --lab N",
            "--headless --ticks 5 --heatmap h.png b.txt | --heatmap goes with --lab N",
            "--headless --lab 5 --heatmap | --heatmap needs a value",
            "--headless --lab 5 --ticks 9 b.txt | --lab takes only --threads, --game-cap, --skip-bad-lines, --report and --heatmap: its players press the keys and each game runs to game over or the cap",
            "--headless --lab 5 --replay r.json | --lab takes only --threads, --game-cap, --skip-bad-lines, --report and --heatmap: its players press the keys and each game runs to game over or the cap"})
    void refusesBadCommandLinesSayingWhy(String commandLine, String message) {
        assertThatThrownBy(() -> HeadlessOptions.parse(List.of(commandLine.split(" "))))
                .isInstanceOf(HeadlessOptions.BadArguments.class).hasMessage(message);
    }
}
