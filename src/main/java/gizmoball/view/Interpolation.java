package gizmoball.view;

import gizmoball.model.Board;
import gizmoball.model.gizmo.BarView;
import gizmoball.model.gizmo.Gizmo;
import gizmoball.model.loop.BallView;
import java.util.HashMap;
import java.util.Map;
import physics.Vect;

/**
 * Where the board view draws balls and turning bars between two ticks, so that slow motion (a tick every 1/8 s at
 * 1/8x) moves smoothly at the display's rate: the drawing runs one tick behind the model and goes from the board
 * at the tick before the last to the board at the last, as far as the real time since has come towards the next
 * tick ({@link #setFraction}). Only the drawing: the model, its ticks and replays are untouched.
 * <p>
 * A free ball moves in a straight line between ticks; a bar (a flipper's, a spinner's) turns about its pivot. What was not there at the
 * tick before (a ball placed, fired from an absorber, caught by one) and any change other than a tick (an edit, a
 * load, Reset) are drawn where they are.
 */
final class Interpolation {
    private Map<String, Vect> ballsBefore = Map.of();
    private Map<String, Vect> ballsNow = Map.of();
    private Map<String, Vect> tipsBefore = Map.of();
    private Map<String, Vect> tipsNow = Map.of();
    private double fraction = 1;

    /** The board ticked: the last tick's positions become the ones drawn from. */
    void ticked(Board board) {
        ballsBefore = ballsNow;
        tipsBefore = tipsNow;
        take(board);
    }

    /** The board changed otherwise: nothing to draw from, everything is drawn where it is. */
    void reset(Board board) {
        take(board);
        ballsBefore = ballsNow;
        tipsBefore = tipsNow;
    }

    /** How far real time has come from the last tick towards the next, 0..1 (1 when the game is stopped). */
    void setFraction(double f) {
        fraction = Math.max(0, Math.min(1, f));
    }

    double fraction() {
        return fraction;
    }

    /** Where to draw the ball's centre. */
    Vect ball(BallView ball) {
        Vect before = ballsBefore.get(ball.name());
        Vect now = ballsNow.get(ball.name());
        if (before == null || now == null || !now.equals(ball.position())) {
            return ball.position();
        }
        return before.plus(now.minus(before).times(fraction));
    }

    /** Where to draw the bar's tip: turned the short way about its pivot from its angle at the tick before. */
    Vect tip(BarView bar) {
        Vect before = tipsBefore.get(bar.name());
        Vect now = bar.tip();
        if (before == null || !now.equals(tipsNow.get(bar.name()))) {
            return now;
        }
        Vect pivot = bar.pivot();
        double from = StrictMath.atan2(before.y() - pivot.y(), before.x() - pivot.x());
        double to = StrictMath.atan2(now.y() - pivot.y(), now.x() - pivot.x());
        double turn = StrictMath.IEEEremainder(to - from, 2 * Math.PI);
        double angle = from + turn * fraction;
        double length = now.minus(pivot).length();
        return pivot.plus(new Vect(length * StrictMath.cos(angle), length * StrictMath.sin(angle)));
    }

    private void take(Board board) {
        Map<String, Vect> balls = new HashMap<>();
        for (BallView ball : board.balls()) {
            if (!ball.isCaptured()) {
                balls.put(ball.name(), ball.position());
            }
        }
        Map<String, Vect> tips = new HashMap<>();
        for (Gizmo gizmo : board.gizmos()) {
            if (gizmo instanceof BarView bar) {
                tips.put(bar.name(), bar.tip());
            }
        }
        ballsNow = balls;
        tipsNow = tips;
    }
}
