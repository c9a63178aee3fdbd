package gizmoball.boardfile;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.List;
import org.junit.jupiter.api.Test;

/** Issue 23, item 8: the command a misspelt word was meant to be. */
class NearestWordTest {
    private static final List<String> KNOWN = CommandWord.spellings();

    @Test
    void distancesCountEditsAndSwapsOfNeighbours() {
        assertThat(NearestWord.distance("sqaure", "square")).isEqualTo(1);
        assertThat(NearestWord.distance("circel", "circle")).isEqualTo(1);
        assertThat(NearestWord.distance("ball", "ball")).isZero();
        assertThat(NearestWord.distance("", "move")).isEqualTo(4);
        assertThat(NearestWord.distance("kitten", "sitting")).isEqualTo(3);
    }

    @Test
    void aSlipOfTheFingersFindsItsCommandInAnyLetterCase() {
        assertThat(NearestWord.among("SQAURE", KNOWN)).contains("Square");
        assertThat(NearestWord.among("rotat", KNOWN)).contains("Rotate");
        assertThat(NearestWord.among("Bal", KNOWN)).contains("Ball");
    }

    @Test
    void aWordFarFromEveryCommandHasNoNearest() {
        assertThat(NearestWord.among("Foo", KNOWN)).isEmpty();
        assertThat(NearestWord.among("Bumper", KNOWN)).isEmpty();
        assertThat(NearestWord.among("Teleporter", KNOWN)).isEmpty();
    }
}
