package gizmoball.editor;

import gizmoball.boardfile.KeyCodes;
import gizmoball.model.gizmo.GizmoKind;

import java.awt.event.KeyEvent;
import java.util.Arrays;
import java.util.Optional;

/** The build-mode tools, in palette order, each with the key that selects it and the hint the status line shows. */
public enum Tool {
    SQUARE(KeyEvent.VK_S, GizmoKind.SQUARE, "click a cell to place a square bumper; drag to fill a rectangle"),
    CIRCLE(KeyEvent.VK_C, GizmoKind.CIRCLE, "click a cell to place a circle bumper; drag to fill a rectangle"),
    TRIANGLE(KeyEvent.VK_T, GizmoKind.TRIANGLE, "click a cell to place a triangle bumper; drag to fill a rectangle"),
    LEFT_FLIPPER(KeyEvent.VK_L, GizmoKind.LEFT_FLIPPER, "click the top-left cell of a 2x2 box; drag to fill a rectangle"),
    RIGHT_FLIPPER(KeyEvent.VK_R, GizmoKind.RIGHT_FLIPPER, "click the top-left cell of a 2x2 box; drag to fill a rectangle"),
    ABSORBER(KeyEvent.VK_A, GizmoKind.ABSORBER, "drag out a rectangle of cells"),
    SINK(KeyEvent.VK_I, GizmoKind.SINK, "click a cell to place a sink: a ball that touches it leaves the board"),
    ACCELERATOR(KeyEvent.VK_E, GizmoKind.ACCELERATOR,
            "click a cell to place an accelerator: a round bumper that sends the ball away faster"),
    SPAWNER(KeyEvent.VK_W, GizmoKind.SPAWNER,
            "click a cell to place a spawner: triggered, it adds a ball at its mouth (turn it to aim the mouth)"),
    GATE(KeyEvent.VK_G, GizmoKind.GATE, "click a cell to place a gate: solid, or open while triggers say"),
    DROP_TARGET(KeyEvent.VK_J, GizmoKind.DROP_TARGET,
            "click a cell to place a drop target: solid until a ball hits it, then down until a trigger raises it"),
    SPINNER(KeyEvent.VK_Y, GizmoKind.SPINNER,
            "click the top-left cell of a 2x2 box to place a spinner: a bar that turns without end"),
    BALL("Ball", KeyEvent.VK_B, null, "click to place a ball; drag before releasing to give it a velocity"),
    SELECT("Select / Move", KeyEvent.VK_M, null, "click to select (Shift+click adds), drag from empty space to select many, drag what is selected"
            + " to move it, drag an absorber's handle to resize it"),
    ROTATE("Rotate", KeyEvent.VK_O, null, "click a gizmo to turn it 90 degrees clockwise"),
    DELETE("Delete", KeyEvent.VK_D, null, "click a gizmo or ball to delete it"),
    CONNECT("Connect", KeyEvent.VK_N, null,
            "click the trigger source (outside the board = outer walls), then the gizmo it drives"),
    DISCONNECT("Disconnect", KeyEvent.VK_X, null, "click the source, then the target of the connection to remove"),
    KEY_CONNECT("Key Connect", KeyEvent.VK_K, null, "click a gizmo, press the key, then choose down or up"),
    KEY_DISCONNECT("Key Disconnect", KeyEvent.VK_U, null, "click a gizmo, then press the key to unbind");

    private final String label;
    private final int shortcut;
    private final GizmoKind kind;
    private final String hint;

    Tool(String label, int shortcut, GizmoKind kind, String hint) {
        this.label = label;
        this.shortcut = shortcut;
        this.kind = kind;
        this.hint = hint;
    }

    /** A placement tool, labelled with its kind's name in title case: "Left Flipper". */
    Tool(int shortcut, GizmoKind kind, String hint) {
        this(titleCase(kind.displayName()), shortcut, kind, hint);
    }

    private static String titleCase(String words) {
        StringBuilder title = new StringBuilder(words.length());
        for (String word : words.split(" ")) {
            title.append(title.length() == 0 ? "" : " ").append(Character.toUpperCase(word.charAt(0)))
                    .append(word.substring(1));
        }
        return title.toString();
    }

    public String label() {
        return label;
    }

    /** KeyEvent code of the (unmodified) key that selects this tool in build mode. */
    public int shortcut() {
        return shortcut;
    }

    /** The gizmo kind this tool places, if it is a placement tool. */
    public Optional<GizmoKind> kind() {
        return Optional.ofNullable(kind);
    }

    public String hint() {
        return hint;
    }

    /** "Square (S)" style text for tooltips and the status line. */
    public String labelWithShortcut() {
        return label + " (" + KeyCodes.name(shortcut) + ")";
    }

    public static Optional<Tool> forShortcut(int keyCode) {
        return Arrays.stream(values()).filter(t -> t.shortcut == keyCode).findFirst();
    }
}
