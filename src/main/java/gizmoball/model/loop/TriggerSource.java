package gizmoball.model.loop;

/**
 * What a connection listens to: a gizmo or the outer walls. Stage 4 of a tick reports the one a ball hit (as a
 * {@link Struck}), and stage 5 triggers the connections from it.
 *
 * <p>Its {@link #toString()} is its {@link #name()}, so that messages ("connection OuterWalls -&gt; A already
 * exists") read as a board file does.
 */
public sealed interface TriggerSource extends Struck {
    TriggerSource OUTER_WALLS = new OuterWalls();

    /** The name of the source as board files and the editor give it. */
    String name();

    /** The gizmo named {@code name} as a source. */
    static TriggerSource gizmo(String name) {
        return new OfGizmo(name);
    }

    /**
     * The source a name means: {@link OuterWalls#NAME} the outer walls, any other the gizmo of that name. The one
     * place where the walls' name is read (board files, the editor's selection).
     */
    static TriggerSource named(String name) {
        return OuterWalls.NAME.equals(name) ? OUTER_WALLS : gizmo(name);
    }

    /** The four walls around the board, all one source. */
    record OuterWalls() implements TriggerSource {
        /** Their name in board files and the editor, reserved: no gizmo or ball may have it. */
        public static final String NAME = "OuterWalls";

        @Override
        public String name() {
            return NAME;
        }

        @Override
        public String toString() {
            return NAME;
        }
    }

    /** The gizmo named {@code gizmo}. */
    record OfGizmo(String gizmo) implements TriggerSource {
        @Override
        public String name() {
            return gizmo;
        }

        @Override
        public String toString() {
            return gizmo;
        }
    }
}
