package gizmoball.boardfile;

import static gizmoball.boardfile.Decimals.format;

import gizmoball.model.Board;
import gizmoball.model.game.Nudge;
import gizmoball.model.game.Tilt;
import java.util.List;
import java.util.Optional;
import java.util.OptionalLong;

/**
 * The commands of a board's game, all ours ({@code #@}): how many balls, the extra ball, drains, the gizmos' own
 * points, the nudge, the tilt and the ball save (docs/board-files.md). Each states one rule of the board's
 * {@link gizmoball.model.game.GameRules}.
 */
public sealed interface GameLine extends Command {

    /** {@code #@Balls <n>}: how many balls a game on the board has. */
    record BallsPerGame(int balls) implements GameLine, Command.OfTheBoard {
        public void applyTo(Board board) {
            board.setBallsPerGame(balls);
        }

        public String toLine() {
            return CommandWord.BALLS.line(balls);
        }
    }

    /** {@code #@ExtraBall <score>}: reaching that score gives one more ball, once a game. */
    record ExtraBall(long score) implements GameLine, Command.OfTheBoard {
        public void applyTo(Board board) {
            board.setExtraBallAt(OptionalLong.of(score));
        }

        public String toLine() {
            return CommandWord.EXTRA_BALL.line(score);
        }
    }

    /** {@code #@Drain <absorber>}: a ball the absorber captures is lost. */
    record Drain(String absorber) implements GameLine {
        public void applyTo(Board board) {
            board.setDrain(absorber, true);
        }

        public String toLine() {
            return CommandWord.DRAIN.line(absorber);
        }

        public List<String> references() {
            return List.of(absorber);
        }
    }

    /** {@code #@Nudge <speed> <left-key> <right-key> <up-key>}: the board can be nudged with those keys. */
    record NudgeLine(Nudge nudge) implements GameLine, Command.OfTheBoard {
        public void applyTo(Board board) {
            board.setNudge(Optional.of(nudge));
        }

        public String toLine() {
            return CommandWord.NUDGE.line(format(nudge.speed()), nudge.leftKey(), nudge.rightKey(), nudge.upKey());
        }
    }

    /** {@code #@Tilt <nudges> <seconds>}: that many nudges within that time tilt the game. */
    record TiltLine(Tilt tilt) implements GameLine, Command.OfTheBoard {
        public void applyTo(Board board) {
            board.setTilt(tilt);
        }

        public String toLine() {
            return CommandWord.TILT.line(tilt.nudges(), format(tilt.seconds()));
        }
    }

    /** {@code #@BallSave <seconds>}: a ball drained that soon after its launch is given back, once. */
    record BallSave(double seconds) implements GameLine, Command.OfTheBoard {
        public void applyTo(Board board) {
            board.setBallSave(seconds);
        }

        public String toLine() {
            return CommandWord.BALL_SAVE.line(format(seconds));
        }
    }

    /** {@code #@Points <gizmo> <points>}: what a real hit on the gizmo scores. */
    record Points(String gizmo, int points) implements GameLine {
        public void applyTo(Board board) {
            board.setPoints(gizmo, points);
        }

        public String toLine() {
            return CommandWord.POINTS.line(gizmo, points);
        }

        public List<String> references() {
            return List.of(gizmo);
        }

        public Subject subject() {
            return new Subject("points", gizmo);
        }
    }
}
