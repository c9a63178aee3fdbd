package gizmoball.view;

import java.awt.BorderLayout;
import java.awt.Font;
import java.util.Locale;
import javax.swing.BorderFactory;
import javax.swing.Box;
import javax.swing.BoxLayout;
import javax.swing.JLabel;
import javax.swing.JPanel;

/** The line under the board: board name, running or stopped and at what speed, simulated time, measured frame rate, last message. */
public final class StatusLine extends JPanel {
    private final JLabel board = new JLabel();
    private final JLabel state = new JLabel();
    private final JLabel time = new JLabel();
    private final JLabel fps = new JLabel();
    private final JLabel message = new JLabel(" ");

    public StatusLine() {
        super(new BorderLayout());
        setBorder(BorderFactory.createEmptyBorder(3, 8, 3, 8));
        JPanel facts = new JPanel();
        facts.setLayout(new BoxLayout(facts, BoxLayout.X_AXIS));
        Font fixed = new Font(Font.MONOSPACED, Font.PLAIN, message.getFont().getSize());
        time.setFont(fixed);
        fps.setFont(fixed);
        for (JLabel label : new JLabel[] {board, state, time, fps}) {
            facts.add(label);
            facts.add(Box.createHorizontalStrut(16));
        }
        add(facts, BorderLayout.WEST);
        add(message, BorderLayout.CENTER);
        message.setName("status.message");
    }

    /** The facts of the moment; cheap when nothing changed (labels only repaint on a new text). */
    public void show(String boardName, String mode, boolean running, String speed, double simulatedTime,
                     int framesPerSecond) {
        setText(board, boardName);
        setText(state, mode + (running ? " - running" : " - stopped") + " at " + speed);
        setText(time, String.format(Locale.ROOT, "t = %.2f s", simulatedTime));
        setText(fps, String.format(Locale.ROOT, "%3d fps", framesPerSecond));
    }

    /** A message for the player (a refused edit, a saved file, an error), kept until the next one. */
    public void showMessage(String text) {
        setText(message, text);
    }

    public String message() {
        return message.getText();
    }

    /** Everything the line says, as one string. */
    public String text() {
        return String.join("   ", board.getText(), state.getText(), time.getText(), fps.getText(), message.getText());
    }

    private static void setText(JLabel label, String text) {
        if (!text.equals(label.getText())) {
            label.setText(text);
        }
    }
}
