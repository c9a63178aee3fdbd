package gizmoball.editor;

import gizmoball.boardfile.Decimals;
import gizmoball.boardfile.KeyCodes;
import gizmoball.model.KeyBinding;
import gizmoball.model.game.GameRules;
import gizmoball.model.game.Nudge;
import gizmoball.model.game.Tilt;
import gizmoball.model.gizmo.Gizmo;
import gizmoball.model.gizmo.Rgb;
import gizmoball.model.gizmo.Setting;
import gizmoball.model.loop.BallView;
import gizmoball.model.loop.TriggerSource;
import java.util.Locale;
import java.util.Optional;
import java.util.OptionalDouble;
import java.util.OptionalLong;
import java.util.regex.Pattern;

/**
 * What the properties panel changes, each one undo step of its editor with the reason for a refusal on the status
 * line: the board's constants and game (with its nudge, tilt and ball save), a gizmo's points, setting, drain, colour, cell and name, a ball's place and
 * velocity, and the removal of one connection or key binding. The same value again is no edit.
 */
public final class PropertyEdits {
    private static final Pattern HEX_COLOUR = Pattern.compile("[0-9a-fA-F]{6}");

    private final Editor editor;

    PropertyEdits(Editor editor) {
        this.editor = editor;
    }

    /** Sets gravity and friction together (one undo step); unchanged values are no edit. */
    public boolean setConstants(double gravity, double mu, double mu2) {
        if (gravity == editor.board().gravity() && mu == editor.board().mu() && mu2 == editor.board().mu2()) {
            return true;
        }
        return editor.edit("Gravity " + gravity + " L/s\u00b2, friction mu " + mu + "/s, mu2 " + mu2 + "/L", b -> {
            b.setGravity(gravity);
            b.setFriction(mu, mu2);
        });
    }

    /**
     * The board's game: balls per game and the extra-ball score (empty for none), one undo step; unchanged values are
     * no edit.
     */
    public boolean setGame(int ballsPerGame, OptionalLong extraBallAt) {
        GameRules rules = editor.board().gameRules();
        if (rules.ballsPerGame() == ballsPerGame && rules.extraBallAt().equals(extraBallAt)) {
            return true;
        }
        return editor.edit(ballsPerGame + " balls a game" + (extraBallAt.isPresent() ? ", an extra ball at "
                + extraBallAt.getAsLong() : ", no extra ball"), b -> {
                    b.setBallsPerGame(ballsPerGame);
                    b.setExtraBallAt(extraBallAt);
                });
    }

    /**
     * The nudge's speed (empty: the board cannot be nudged; its keys kept, the arrows for a new one), the tilt's nudges
     * and seconds and the ball save's seconds, as one undo step (the same values again are no edit).
     */
    public boolean setTable(OptionalDouble nudgeSpeed, double tiltNudges, double tiltSeconds, double ballSaveSeconds) {
        GameRules rules = editor.board().gameRules();
        Nudge keys = rules.nudge().orElse(Nudge.DEFAULT);
        Optional<Nudge> nudge;
        Tilt tilt;
        try {
            nudge = nudgeSpeed.isEmpty() ? Optional.empty() : Optional.of(new Nudge(nudgeSpeed.getAsDouble(),
                    keys.leftKey(), keys.rightKey(), keys.upKey()));
            if (tiltNudges != Math.rint(tiltNudges)) {
                throw new IllegalArgumentException("a tilt comes with a whole number of nudges, not " + tiltNudges);
            }
            tilt = new Tilt((int) tiltNudges, tiltSeconds);
        } catch (IllegalArgumentException refused) {
            return editor.refuse(refused.getMessage());
        }
        if (rules.nudge().equals(nudge) && rules.tilt().equals(tilt) && rules.ballSaveSeconds() == ballSaveSeconds) {
            return true;
        }
        return editor.edit("Nudge " + nudge.map(n -> Decimals.format(n.speed()) + " L/s").orElse("off")
                + ", tilt at " + tilt.nudges() + " nudges in " + Decimals.format(tilt.seconds()) + " s, ball save "
                + Decimals.format(ballSaveSeconds) + " s", b -> {
                    b.setNudge(nudge);
                    b.setTilt(tilt);
                    b.setBallSave(ballSaveSeconds);
                });
    }

    /** What a real hit on the gizmo scores (one undo step; the same value again is no edit). */
    public boolean setPoints(String gizmo, int points) {
        Optional<Gizmo> target = editor.board().gizmo(gizmo);
        if (target.isEmpty()) {
            editor.say("No gizmo named " + gizmo);
            return false;
        }
        if (editor.board().gameRules().pointsOf(gizmo, target.get().kind()) == points) {
            return true;
        }
        return editor.edit(gizmo + " scores " + points, b -> b.setPoints(gizmo, points));
    }

    /**
     * Gives the gizmo the value its kind holds beyond its place ({@link Setting}: a factor, a speed, a velocity, a
     * pair), one undo step; the same value again is no edit.
     */
    public boolean set(String gizmo, Setting setting) {
        if (editor.board().gizmo(gizmo).map(Gizmo::setting).filter(setting::equals).isPresent()) {
            return true;
        }
        return editor.edit(setting.said(gizmo), b -> b.set(gizmo, setting));
    }

    /** Makes an absorber a drain of the game or an ordinary absorber (one undo step). */
    public boolean setDrain(String absorber, boolean drain) {
        if (editor.board().gameRules().isDrain(absorber) == drain) {
            return true;
        }
        return editor.edit(absorber + (drain ? " is a drain: a ball it captures is lost" : " is no drain"),
                b -> b.setDrain(absorber, drain));
    }

    /** Sets a ball's centre and velocity (one undo step); the ball keeps its place in the board's order. */
    public boolean setBall(String name, double x, double y, double vx, double vy) {
        Optional<BallView> ball = editor.board().ball(name);
        if (ball.isEmpty()) {
            editor.say("No ball named " + name);
            return false;
        }
        BallView b0 = ball.get();
        boolean samePlace = b0.position().x() == x && b0.position().y() == y;
        boolean sameVelocity = b0.velocity().x() == vx && b0.velocity().y() == vy;
        if (samePlace && sameVelocity) {
            return true;
        }
        return editor.edit("Ball " + name + " updated", b -> {
            if (!samePlace) {
                b.moveBall(name, x, y);
            }
            if (!sameVelocity) {
                b.setBallVelocity(name, vx, vy);
            }
        });
    }

    /**
     * Gives a gizmo its own colour from text: {@code #rrggbb} (the # optional), or empty for its kind's colour.
     * One undo step; the same colour again is no edit.
     */
    public boolean setColour(String gizmo, String text) {
        Optional<Gizmo> target = editor.board().gizmo(gizmo);
        if (target.isEmpty()) {
            editor.say("No gizmo named " + gizmo);
            return false;
        }
        String hex = text.strip();
        hex = hex.startsWith("#") ? hex.substring(1) : hex;
        Optional<Rgb> colour;
        if (hex.isEmpty()) {
            colour = Optional.empty();
        } else if (HEX_COLOUR.matcher(hex).matches()) {
            colour = Optional.of(Rgb.of(Integer.parseInt(hex, 16)));
        } else {
            return editor.refuse("Colour '" + text.strip() + "' is not #rrggbb (such as #99b3ff); leave it empty for "
                    + "the colour of the kind");
        }
        if (colour.equals(target.get().colour())) {
            return true;
        }
        return editor.edit(colour.map(c -> gizmo + " coloured " + hex(c))
                        .orElse(gizmo + " back to the colour of its kind"), b -> b.setColour(gizmo, colour));
    }

    /** {@code #rrggbb}, as the properties panel shows a colour. */
    public static String hex(Rgb colour) {
        return String.format(Locale.ROOT, "#%06x", colour.packed());
    }

    /** Removes one connection (from the properties panel's list). */
    public boolean disconnect(TriggerSource source, String target) {
        return editor.edit("Disconnected " + source + " \u2192 " + target, b -> b.disconnect(source, target));
    }

    /** Removes one key binding (from the properties panel's list). */
    public boolean unbind(KeyBinding binding) {
        return editor.edit("Removed " + KeyCodes.describe(binding),
                b -> b.unbindKey(binding.keyCode(), binding.edge(), binding.gizmo()));
    }


    /** Moves a gizmo to the cell typed for it (one undo step); the same cell is no edit. */
    public boolean moveGizmoTo(String gizmo, int x, int y) {
        Optional<Gizmo> g = editor.board().gizmo(gizmo);
        if (g.isEmpty()) {
            return editor.refuse("No gizmo named " + gizmo);
        }
        if (g.get().x() == x && g.get().y() == y) {
            return true;
        }
        return editor.edit("Moved " + gizmo + " to (" + x + "," + y + ")", b -> b.moveGizmo(gizmo, x, y));
    }

    /** Renames a gizmo or ball; its connections, key bindings, colour and points follow (one undo step). */
    public boolean rename(String name, String newName) {
        String typed = newName.strip();
        if (typed.equals(name)) {
            return true;
        }
        boolean done = editor.edit("Renamed " + name + " to " + typed, b -> Transfer.rename(b, name, typed));
        if (done) {
            editor.select(typed);
        }
        return done;
    }
}
