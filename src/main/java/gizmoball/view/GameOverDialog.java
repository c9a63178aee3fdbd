package gizmoball.view;

import java.awt.Component;
import java.awt.GridLayout;
import java.awt.event.WindowAdapter;
import java.awt.event.WindowEvent;
import java.text.NumberFormat;
import java.util.Locale;
import java.util.Optional;
import java.util.OptionalInt;
import javax.swing.JDialog;
import javax.swing.JLabel;
import javax.swing.JOptionPane;
import javax.swing.JPanel;
import javax.swing.JTextField;

/** Game over: the final score and, when it ranks on the board's table, the place it takes and a name for it. */
public final class GameOverDialog {
    public static final String TITLE = "Game over";

    private GameOverDialog() {
    }

    /**
     * Shows the dialog (modal) and returns the name given for the table; empty when the score does not rank or the
     * player declined. {@code who} names the player of a game of several ("Player 2"), empty for a game of one;
     * {@code place} is 0 for the best.
     */
    public static Optional<String> show(Component parent, String who, long score, OptionalInt place,
                                        String suggestedName, String newGameShortcut) {
        JPanel panel = new JPanel(new GridLayout(0, 1, 0, 6));
        JLabel total = new JLabel((who.isEmpty() ? "Final score: " : who + ", final score: ")
                + NumberFormat.getIntegerInstance(Locale.ROOT).format(score));
        total.setName("gameover.score");
        total.setFont(total.getFont().deriveFont(total.getFont().getSize2D() * 1.6f));
        panel.add(total);
        JTextField name = new JTextField(suggestedName, 20);
        name.setName("gameover.name");
        if (place.isPresent()) {
            JLabel ranks = new JLabel(place.getAsInt() == 0 ? "A new best for this board! Your name for the table:"
                    : "Number " + (place.getAsInt() + 1) + " on this board's table. Your name for it:");
            ranks.setName("gameover.place");
            panel.add(ranks);
            panel.add(name);
        }
        panel.add(new JLabel(newGameShortcut + " starts a new game."));
        String[] options = place.isPresent() ? new String[] {"Keep my score", "Skip"} : new String[] {"OK"};
        JOptionPane pane = new JOptionPane(panel, JOptionPane.INFORMATION_MESSAGE, JOptionPane.DEFAULT_OPTION, null,
                options, options[0]);
        JDialog dialog = pane.createDialog(parent, TITLE);
        dialog.setName("gameover.dialog");
        if (place.isPresent()) {
            name.selectAll();
            dialog.addWindowFocusListener(new WindowAdapter() {
                @Override
                public void windowGainedFocus(WindowEvent e) {
                    name.requestFocusInWindow();
                }
            });
            name.addActionListener(e -> pane.setValue(options[0]));
        }
        dialog.setVisible(true);
        dialog.dispose();
        boolean keep = place.isPresent() && options[0].equals(pane.getValue()) && !name.getText().isBlank();
        return keep ? Optional.of(name.getText().strip()) : Optional.empty();
    }
}
