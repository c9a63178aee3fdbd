package gizmoball.boardfile;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.List;
import org.junit.jupiter.api.Test;

class BoardFileLexerTest {

    @Test
    void blankAndCommentLinesAreDroppedButLineNumbersKept() {
        String text = "# a comment\n\nSquare S 1 2\n   \n  # indented comment\nCircle C 3 4\n";
        assertThat(BoardFileLexer.commandLines(text)).containsExactly(
                new SourceLine(3, "Square S 1 2"), new SourceLine(6, "Circle C 3 4"));
    }

    @Test
    void crLfAndCrCrLfEndOneLineEach() {
        assertThat(BoardFileLexer.commandLines("Square S 1 2\r\nCircle C 3 4\r\r\n\r\r\nRotate S"))
                .containsExactly(new SourceLine(1, "Square S 1 2"), new SourceLine(2, "Circle C 3 4"),
                        new SourceLine(4, "Rotate S"));
    }

    @Test
    void lastLineWithoutNewlineIsRead() {
        assertThat(BoardFileLexer.commandLines("Square S 1 2\nGravity 10")).extracting(SourceLine::text)
                .containsExactly("Square S 1 2", "Gravity 10");
    }

    @Test
    void byteOrderMarkIsIgnored() {
        assertThat(BoardFileLexer.commandLines("\uFEFFSquare S 1 2")).containsExactly(new SourceLine(1, "Square S 1 2"));
    }

    @Test
    void wordsAreSplitOnAnyRunOfWhitespace() {
        assertThat(BoardFileLexer.words("  \tSquare   S1\t 1  2 \r")).isEqualTo(List.of("Square", "S1", "1", "2"));
    }

    @Test
    void emptyTextHasNoCommands() {
        assertThat(BoardFileLexer.commandLines("")).isEmpty();
        assertThat(BoardFileLexer.commandLines("\n\r\n  \n")).isEmpty();
    }
}
