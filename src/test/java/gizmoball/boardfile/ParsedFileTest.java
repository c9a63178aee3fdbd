package gizmoball.boardfile;

import static org.assertj.core.api.Assertions.assertThat;

import org.junit.jupiter.api.Test;

class ParsedFileTest {

    @Test
    void reportsEveryBadLineWithItsNumberTextAndReason() {
        String text = "Square S 1 2\r\n\r\nRhombus B 1 2\r\n# comment\r\nCircle C x 3\r\nRotate S\r\nGravity";
        ParsedFile parsed = ParsedFile.parse("board.txt", text);

        assertThat(parsed.commands()).extracting(line -> line.line().number()).containsExactly(1, 6);
        assertThat(parsed.errors()).containsExactly(
                new BoardFileError("board.txt", 3, "Rhombus B 1 2",
                        "Rhombus B: an extension of another implementation, not part of the format"),
                new BoardFileError("board.txt", 5, "Circle C x 3", "x 'x' is not a number"),
                new BoardFileError("board.txt", 7, "Gravity",
                        "wrong number of arguments: Gravity takes 1 (Gravity <g>), found 0"));
        assertThat(parsed.errors().get(1)).hasToString("board.txt:5: x 'x' is not a number: Circle C x 3");
    }

    @Test
    void exceptionMessageListsAllErrors() {
        ParsedFile parsed = ParsedFile.parse("b", "Foo\nBar");
        BoardFileException refused = new BoardFileException(parsed.errors());
        assertThat(refused).hasMessage("2 bad lines:\nb:1: unknown command 'Foo': Foo\nb:2: unknown command 'Bar': Bar");
        assertThat(refused.errors()).hasSize(2);
    }
}
