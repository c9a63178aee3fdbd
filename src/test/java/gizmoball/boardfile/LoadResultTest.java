package gizmoball.boardfile;

import static org.assertj.core.api.Assertions.assertThat;

import org.junit.jupiter.api.Test;

class LoadResultTest {
    @Test
    void aFileWhoseEveryLineIsBadKeepsNothing() {
        LoadResult result = BoardFiles.loadSkippingBadLines("bad.txt", "Bogus 1\nSquare S x 1\n# a comment\n\n");
        assertThat(result.skippedLines()).hasSize(2);
        assertThat(result.keptNothing()).isTrue();
    }

    @Test
    void oneGoodGizmoIsSomethingKept() {
        assertThat(BoardFiles.loadSkippingBadLines("f.txt", "Bogus 1\nSquare S 1 1\n").keptNothing()).isFalse();
    }

    @Test
    void aGoodSettingAloneIsSomethingKept() {
        assertThat(BoardFiles.loadSkippingBadLines("f.txt", "Bogus 1\nGravity 10\n").keptNothing()).isFalse();
    }
}
