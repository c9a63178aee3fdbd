package gizmoball.boardfile;

import gizmoball.model.gizmo.Setting;
import gizmoball.model.Board;
import gizmoball.model.game.GameRules;
import gizmoball.model.game.Points;
import gizmoball.model.gizmo.Gizmo;
import gizmoball.model.BoardEditException;
import gizmoball.model.KeyEdge;
import gizmoball.model.gizmo.Action;
import gizmoball.model.gizmo.GizmoKind;
import gizmoball.model.gizmo.Order;
import gizmoball.model.gizmo.Rgb;
import gizmoball.model.loop.TriggerSource;
import java.util.List;
import java.util.Optional;
import java.util.OptionalLong;
import java.util.Random;

/** Random boards built through the board's own editing operations, for property tests. */
final class RandomBoards {
    /** Names of any non-space characters, as peer files use: digits first, punctuation, mixed case. */
    private static final String NAME_CHARACTERS =
            "abcXYZ0123456789_-.!$%&*+/:;<=>?@[]^{|}~'\"`,()#\\";
    private static final int[] KEY_CODES = {32, 47, 65, 76, 81, 87, 90, 10, 37, 38, 39, 40, 127, 112};
    private static final GizmoKind[] PLACEABLE = {GizmoKind.SQUARE, GizmoKind.CIRCLE, GizmoKind.TRIANGLE,
            GizmoKind.LEFT_FLIPPER, GizmoKind.RIGHT_FLIPPER};
    /** Issue 22's kinds that the property test draws (a spinner with a speed of its own, sometimes). */
    private static final GizmoKind[] EXTENSIONS = {GizmoKind.SINK, GizmoKind.ACCELERATOR, GizmoKind.DROP_TARGET,
            GizmoKind.SPINNER, GizmoKind.PORTAL};

    private final Random random;

    RandomBoards(Random random) {
        this.random = random;
    }

    Board next() {
        Board board = new Board();
        int gizmos = random.nextInt(40);
        for (int i = 0; i < gizmos; i++) {
            attempt(() -> addGizmo(board));
        }
        List<String> names = board.gizmos().stream().map(g -> g.name()).toList();
        for (String name : names) {
            int turns = random.nextInt(4);
            for (int t = 0; t < turns; t++) {
                attempt(() -> board.rotate(name));
            }
            if (random.nextInt(3) == 0) {
                board.setColour(name, Optional.of(Rgb.of(random.nextInt(1 << 24))));
            }
        }
        int balls = random.nextInt(12);
        for (int i = 0; i < balls; i++) {
            attempt(() -> board.addBall(name(), 0.25 + random.nextDouble() * 19.5, 0.25 + random.nextDouble() * 19.5,
                    velocity(), velocity()));
        }
        if (!names.isEmpty()) {
            int connections = random.nextInt(10);
            for (int i = 0; i < connections; i++) {
                TriggerSource source = random.nextInt(5) == 0 ? TriggerSource.OUTER_WALLS : TriggerSource.gizmo(pick(names));
                attempt(() -> board.connect(source, pick(names)));
            }
            int bindings = random.nextInt(8);
            for (int i = 0; i < bindings; i++) {
                attempt(() -> board.bindKey(KEY_CODES[random.nextInt(KEY_CODES.length)],
                        KeyEdge.values()[random.nextInt(KeyEdge.values().length)], pick(names)));
            }
        }
        if (random.nextBoolean()) {
            board.setGravity((random.nextDouble() - 0.3) * 60);
        }
        if (random.nextBoolean()) {
            board.setFriction(random.nextDouble() * 0.1, random.nextDouble() * 0.1);
        }
        addGame(board);
        addExtensions(board);
        return board;
    }

    /**
     * Issue 22, drawn last so that the rest of each board is what it was before: sinks, accelerators (some with a
     * factor of their own), drop targets, spinners (some with a speed of their own) and portals (paired at random),
     * and connections and key bindings with actions and delays.
     */
    private void addExtensions(Board board) {
        if (random.nextBoolean()) {
            return;
        }
        int gizmos = 1 + random.nextInt(4);
        for (int i = 0; i < gizmos; i++) {
            String name = name();
            GizmoKind kind = EXTENSIONS[random.nextInt(EXTENSIONS.length)];
            attempt(() -> board.addGizmo(kind, name, random.nextInt(20), random.nextInt(20)));
            if (kind == GizmoKind.ACCELERATOR && random.nextBoolean()) {
                attempt(() -> board.set(name, new Setting.Factor(1 + random.nextInt(17) / 4.0)));
            }
            if (kind == GizmoKind.SPINNER && random.nextBoolean()) {
                attempt(() -> board.set(name, new Setting.Speed((random.nextBoolean() ? 1 : -1) * (1 + random.nextInt(12)) / 4.0)));
            }
        }
        List<String> portals = board.gizmos().stream().filter(g -> g.kind() == GizmoKind.PORTAL).map(Gizmo::name)
                .toList();
        for (int i = 0; i + 1 < portals.size(); i += 1 + random.nextInt(2)) {
            String first = portals.get(i);
            String second = portals.get(i + 1);
            attempt(() -> board.set(first, Setting.Pair.with(second)));
        }
        List<String> names = board.gizmos().stream().map(Gizmo::name).toList();
        if (names.isEmpty()) {
            return;
        }
        int orders = random.nextInt(4);
        for (int i = 0; i < orders; i++) {
            Gizmo target = board.gizmo(pick(names)).orElseThrow();
            List<Action> actions = target.kind().actions();
            Order order = new Order(random.nextBoolean() ? Optional.empty()
                    : Optional.of(actions.get(random.nextInt(actions.size()))),
                    random.nextBoolean() ? 0 : random.nextInt(40) / 8.0);
            if (random.nextBoolean()) {
                attempt(() -> board.connect(TriggerSource.gizmo(pick(names)), target.name(), order));
            } else {
                attempt(() -> board.bindKey(KEY_CODES[random.nextInt(KEY_CODES.length)],
                        KeyEdge.values()[random.nextInt(KeyEdge.values().length)], target.name(), order));
            }
        }
    }

    /** Drawn last, so that the rest of each board is what it was before boards had games. */
    private void addGame(Board board) {
        if (random.nextBoolean()) {
            return;
        }
        board.setBallsPerGame(1 + random.nextInt(GameRules.MAX_BALLS));
        if (random.nextBoolean()) {
            board.setExtraBallAt(OptionalLong.of(1 + random.nextInt(100_000)));
        }
        for (Gizmo gizmo : board.gizmos()) {
            if (gizmo.kind() == GizmoKind.ABSORBER && random.nextBoolean()) {
                board.setDrain(gizmo.name(), true);
            }
            if (random.nextInt(4) == 0) {
                board.setPoints(gizmo.name(), random.nextInt(2 * Points.LIMIT + 1) - Points.LIMIT);
            }
        }
    }

    private void addGizmo(Board board) {
        int x = random.nextInt(20);
        int y = random.nextInt(20);
        if (random.nextInt(8) == 0) {
            board.addAbsorber(name(), x, y, x + 1 + random.nextInt(20 - x), y + 1 + random.nextInt(Math.min(3, 20 - y)));
        } else {
            board.addGizmo(PLACEABLE[random.nextInt(PLACEABLE.length)], name(), x, y);
        }
    }

    private double velocity() {
        return switch (random.nextInt(4)) {
            case 0 -> 0.0;
            case 1 -> random.nextInt(41) - 20;
            default -> (random.nextDouble() - 0.5) * 300;
        };
    }

    private String name() {
        StringBuilder name = new StringBuilder();
        int length = 1 + random.nextInt(6);
        for (int i = 0; i < length; i++) {
            name.append(NAME_CHARACTERS.charAt(random.nextInt(NAME_CHARACTERS.length())));
        }
        return name.toString();
    }

    private String pick(List<String> names) {
        return names.get(random.nextInt(names.size()));
    }

    /** Random edits may be refused (overlap, duplicate...); the board then stays valid, which is all we need. */
    private static void attempt(Runnable edit) {
        try {
            edit.run();
        } catch (BoardEditException refused) {
            // the board is unchanged: nothing to undo
        }
    }
}
