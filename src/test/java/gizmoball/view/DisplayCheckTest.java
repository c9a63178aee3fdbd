package gizmoball.view;

import static org.assertj.core.api.Assertions.assertThat;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import java.awt.GraphicsEnvironment;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.stream.IntStream;
import org.junit.jupiter.api.Test;

class DisplayCheckTest {
    @Test
    void aDisplayNumberWithNoServerIsUnreachable() {
        int free = IntStream.range(900, 1000).filter(n -> !Files.exists(Path.of("/tmp/.X11-unix/X" + n)))
                .findFirst().orElseThrow();
        assertThat(DisplayCheck.unreachable(":" + free)).hasValueSatisfying(why -> assertThat(why)
                .contains("no X server answers"));
        assertThat(DisplayCheck.unreachable("localhost:" + free + ".0")).isPresent();
    }

    @Test
    void aMalformedDisplayIsUnreachable() {
        assertThat(DisplayCheck.unreachable("nonsense")).isPresent();
        assertThat(DisplayCheck.unreachable(":x")).isPresent();
    }

    @Test
    void theDisplayTheGuiTestsUseAnswers() {
        String display = System.getenv("DISPLAY");
        assumeTrue(display != null && !GraphicsEnvironment.isHeadless(), "no display to check");
        assertThat(DisplayCheck.unreachable(display)).isEmpty();
    }
}
