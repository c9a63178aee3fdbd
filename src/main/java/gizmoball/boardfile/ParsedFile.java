package gizmoball.boardfile;

import java.util.ArrayList;
import java.util.List;

/**
 * A board file read into commands: the well-formed lines in file order and an error for every other line.
 * Every line is looked at, so one read reports all the syntax errors of a file.
 */
record ParsedFile(List<Line> commands, List<BoardFileError> errors) {

    /**
     * A well-formed command and the line it came from, so that later refusals by the model name the line, with
     * how the line was understood if it was not written canonically.
     */
    record Line(SourceLine line, Command command, List<String> notes) {
        Line {
            notes = List.copyOf(notes);
        }
    }

    ParsedFile {
        commands = List.copyOf(commands);
        errors = List.copyOf(errors);
    }

    /** @param source names the file in the errors */
    static ParsedFile parse(String source, String content) {
        List<Line> commands = new ArrayList<>();
        List<BoardFileError> errors = new ArrayList<>();
        for (SourceLine line : BoardFileLexer.commandLines(content)) {
            try {
                CommandParser.Parsed parsed = CommandParser.parse(line.text());
                commands.add(new Line(line, parsed.command(), parsed.notes()));
            } catch (Refusal refusal) {
                errors.add(BoardFileError.at(source, line, refusal.getMessage()));
            }
        }
        return new ParsedFile(commands, errors);
    }
}
