package gizmoball.view.editor;

import gizmoball.boardfile.Decimals;
import gizmoball.editor.EdgeChoice;
import gizmoball.editor.Editor;
import gizmoball.model.KeyEdge;
import gizmoball.model.gizmo.Action;
import gizmoball.model.gizmo.GizmoKind;
import gizmoball.model.gizmo.Order;
import gizmoball.view.BoardPanel;

import javax.swing.BorderFactory;
import javax.swing.ButtonGroup;
import javax.swing.JLabel;
import javax.swing.JMenuItem;
import javax.swing.JPanel;
import javax.swing.JPopupMenu;
import javax.swing.JRadioButtonMenuItem;
import javax.swing.JTextField;
import javax.swing.event.DocumentEvent;
import javax.swing.event.DocumentListener;
import javax.swing.event.PopupMenuEvent;
import javax.swing.event.PopupMenuListener;
import java.awt.BorderLayout;
import java.awt.geom.Point2D;
import java.util.Optional;
import java.util.OptionalDouble;

/**
 * The last step of Key Connect and of Connect: a popup next to the gizmo asks what the binding or the connection makes
 * it do (its own action unless told, or one of the gizmo's actions) and after how many seconds, then for Key Connect
 * whether it acts on key down, key up or both (the arrow keys answer that too: the controller takes them), for
 * Connect just to connect. It closes whenever no answer is awaited.
 */
public final class EdgePopup {
    /** Keeps the popup open when an action is chosen: the edge below is the answer that closes it. */
    private static final String STAYS_OPEN = "RadioButtonMenuItem.doNotCloseOnMouseClick";

    private final Editor controller;
    private final BoardPanel panel;
    private final JPopupMenu popup = new JPopupMenu("Key edge");
    private ButtonGroup actionGroup = new ButtonGroup();
    private final JTextField delay = new JTextField("0", 5);
    private final JPanel delayRow;
    private Optional<Action> chosen = Optional.empty();

    private EdgePopup(Editor controller, BoardPanel panel) {
        this.controller = controller;
        this.panel = panel;
        delay.setName("order.delay");
        delay.setToolTipText("Seconds of play between the key and the action; 0 for at once");
        delay.getDocument().addDocumentListener(new DocumentListener() {
            @Override
            public void insertUpdate(DocumentEvent e) {
                orderChanged();
            }

            @Override
            public void removeUpdate(DocumentEvent e) {
                orderChanged();
            }

            @Override
            public void changedUpdate(DocumentEvent e) {
                orderChanged();
            }
        });
        JPanel delayRow = new JPanel(new BorderLayout(6, 0));
        delayRow.setOpaque(false);
        delayRow.setBorder(BorderFactory.createEmptyBorder(2, 8, 4, 8));
        delayRow.add(new JLabel("after (s)"), BorderLayout.WEST);
        delayRow.add(delay, BorderLayout.CENTER);
        popup.addPopupMenuListener(new PopupMenuListener() {
            @Override
            public void popupMenuWillBecomeVisible(PopupMenuEvent e) {
                // built by show()
            }

            @Override
            public void popupMenuWillBecomeInvisible(PopupMenuEvent e) {
                // an answer, or a cancel handled below
            }

            @Override
            public void popupMenuCanceled(PopupMenuEvent e) {
                if (awaiting(controller)) {
                    controller.cancel();
                }
            }
        });
        this.delayRow = delayRow;
    }

    private static boolean awaiting(Editor controller) {
        return controller.awaitingEdge() || controller.awaitingAction();
    }

    /** The popup of {@code controller}'s Key Connect and Connect over {@code panel}, closing whenever no answer is awaited. */
    public static EdgePopup of(Editor controller, BoardPanel panel) {
        EdgePopup edges = new EdgePopup(controller, panel);
        controller.addStateListener(() -> {
            if (!awaiting(controller) && edges.popup.isVisible()) {
                edges.popup.setVisible(false);
            }
        });
        return edges;
    }

    /**
     * Shows the popup at the top-right corner of the selected gizmo (or mid-board), offering the actions of the gizmo
     * the key will drive.
     */
    public void show() {
        popup.removeAll();
        actionGroup = new ButtonGroup();
        chosen = Optional.empty();
        delay.setText("0");
        Optional<GizmoKind> kind = controller.links().awaitedTargetKind();
        popup.add(sectionTitle("Action"));
        boolean key = controller.awaitingEdge();
        popup.add(action(kind.map(k -> key ? unlessTold(k) : "its own: " + k.defaultAction().word())
                .orElse("its own"), "action.default", Optional.empty(), true));
        // An action that is what "its own" does is not offered again: chosen, it would be saved as no action anyway.
        kind.ifPresent(k -> k.actions().stream().filter(a -> !Optional.of(a).equals(own(k, key)))
                .forEach(a -> popup.add(action(a.word(), "action." + a.word(), Optional.of(a), false))));
        popup.add(delayRow);
        popup.addSeparator();
        if (key) {
            popup.add(item("On key down and up (hold)", "edge.both", () -> controller.links().chooseEdges(EdgeChoice.DOWN_AND_UP)));
            popup.add(item("On key down (press)  \u2193", "edge.down", () -> controller.links().chooseEdges(EdgeChoice.DOWN)));
            popup.add(item("On key up (release)  \u2191", "edge.up", () -> controller.links().chooseEdges(EdgeChoice.UP)));
        } else {
            popup.add(item("Connect", "order.connect", controller.links()::chooseConnection));
        }
        Point2D at = controller.selectedGizmo()
                .map(g -> panel.transform().toScreen(g.x() + g.width(), g.y()))
                .orElse(new Point2D.Double(panel.getWidth() / 2.0, panel.getHeight() / 2.0));
        popup.show(panel, (int) at.getX(), (int) at.getY());
        // Keys keep going to the board (arrow keys answer, Escape cancels).
        panel.requestFocusInWindow();
    }

    /** The order as chosen so far goes to the editor, so that the arrow keys answer with it too. */
    private void orderChanged() {
        OptionalDouble seconds = Decimals.parse(delay.getText().strip());
        if (seconds.isEmpty()) {
            RefusedValue.mark(delay, "\"" + delay.getText().strip() + "\" is not a number of seconds");
        } else {
            RefusedValue.unmark(delay);
            controller.links().orderPending(new Order(chosen, seconds.getAsDouble()));
        }
    }

    /** Gives the answer, or keeps the popup up while the delay does not read. */
    private void answer(Runnable answer) {
        if (Decimals.parse(delay.getText().strip()).isPresent()) {
            answer.run();
        } else {
            controller.tell("The delay \"" + delay.getText().strip() + "\" is not a number of seconds");
            popup.setVisible(true);
        }
    }

    /** The one action the gizmo takes unless told, if it is one for both edges of a key. */
    private static Optional<Action> own(GizmoKind kind, boolean key) {
        if (!key) {
            return Optional.of(kind.defaultAction());
        }
        Action press = KeyEdge.DOWN.actionOf(kind);
        return press == KeyEdge.UP.actionOf(kind) ? Optional.of(press) : Optional.empty();
    }

    /** What the gizmo does when nothing else is chosen: "raise on press, lower on release", "fire". */
    private static String unlessTold(GizmoKind kind) {
        Action press = KeyEdge.DOWN.actionOf(kind);
        Action release = KeyEdge.UP.actionOf(kind);
        return "its own: " + (press == release ? press.word()
                : press.word() + " on press, " + release.word() + " on release");
    }

    private static JLabel sectionTitle(String text) {
        JLabel title = new JLabel(text);
        title.setBorder(BorderFactory.createEmptyBorder(2, 8, 2, 8));
        return title;
    }

    private JRadioButtonMenuItem action(String text, String name, Optional<Action> action, boolean selected) {
        JRadioButtonMenuItem item = new JRadioButtonMenuItem(text, selected);
        item.setName(name);
        item.putClientProperty(STAYS_OPEN, Boolean.TRUE);
        item.addActionListener(e -> {
            chosen = action;
            orderChanged();
        });
        actionGroup.add(item);
        return item;
    }

    private JMenuItem item(String text, String name, Runnable answer) {
        JMenuItem item = new JMenuItem(text);
        item.setName(name);
        item.addActionListener(e -> answer(answer));
        return item;
    }
}
