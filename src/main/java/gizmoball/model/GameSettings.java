package gizmoball.model;

import gizmoball.model.game.GameRules;
import gizmoball.model.game.Nudge;
import gizmoball.model.game.Tilt;
import gizmoball.model.gizmo.GizmoBase;
import gizmoball.model.gizmo.GizmoKind;

import java.util.List;
import java.util.Optional;
import java.util.OptionalLong;
import java.util.function.Supplier;

/**
 * The board's game rules as its editing operations change them (the {@link Board} methods of the same names say
 * what each does): each checks first and throws {@link BoardEditException}, changing nothing, where the rules or the
 * board refuse.
 */
final class GameSettings {
    private GameRules rules = GameRules.DEFAULT;

    GameRules rules() {
        return rules;
    }

    void setBallsPerGame(int balls) {
        change(() -> rules.withBallsPerGame(balls));
    }

    void setDrain(GizmoBase absorber, boolean drain) {
        if (drain && !absorber.kind().canDrain()) {
            throw new BoardEditException("only an absorber can be a drain: " + absorber.name() + " is "
                    + absorber.kind().withArticle() + ", which captures no ball");
        }
        change(() -> rules.withDrain(absorber.name(), drain));
    }

    void setPoints(String gizmo, GizmoKind kind, int points) {
        change(() -> rules.withPoints(gizmo, kind, points));
    }

    void setExtraBallAt(OptionalLong score) {
        change(() -> rules.withExtraBallAt(score));
    }

    /** A nudge whose keys drive nothing of {@code bindings}: a key is a nudge key or a bound key, never both. */
    void setNudge(Optional<Nudge> nudge, List<KeyBinding> bindings) {
        nudge.ifPresent(n -> {
            for (KeyBinding binding : bindings) {
                if (n.wayOf(binding.keyCode()).isPresent()) {
                    throw new BoardEditException("key " + binding.keyCode() + " drives " + binding.gizmo()
                            + ": a nudge key drives nothing else");
                }
            }
        });
        change(() -> rules.withNudge(nudge));
    }

    void setTilt(Tilt tilt) {
        change(() -> rules.withTilt(tilt));
    }

    void setBallSave(double seconds) {
        change(() -> rules.withBallSave(seconds));
    }

    /** The way the key nudges the board, if it is a nudge key. */
    Optional<Nudge.Way> nudgeWay(int keyCode) {
        return rules.nudge().flatMap(n -> n.wayOf(keyCode));
    }

    /** Refuses a key binding of a nudge key. */
    void requireNotNudging(int keyCode) {
        if (nudgeWay(keyCode).isPresent()) {
            throw new BoardEditException("key " + keyCode + " nudges the board: it drives nothing else");
        }
    }

    /** The gizmo {@code name} was deleted: its drain and points go with it. */
    void forget(String name) {
        rules = rules.without(name);
    }

    void reset() {
        rules = GameRules.DEFAULT;
    }

    void copyFrom(GameSettings source) {
        rules = source.rules;
    }

    private void change(Supplier<GameRules> changed) {
        try {
            rules = changed.get();
        } catch (IllegalArgumentException refused) {
            throw new BoardEditException(refused.getMessage());
        }
    }
}
