package gizmoball.view;

import java.awt.Dimension;
import java.awt.Font;
import java.awt.FontMetrics;
import java.awt.Insets;
import java.util.List;
import java.util.Locale;
import java.util.stream.Collectors;
import java.util.stream.Stream;
import javax.swing.BorderFactory;
import javax.swing.JLabel;
import javax.swing.JPanel;

/**
 * The line under the board: board name, mode, running or stopped and at what speed, simulated time, the frame rate while the
 * game runs, and the last message. When the line is too narrow the message keeps its room: the frame rate,
 * the time and the state give way in that order, and the board name is shortened in its middle (keeping its
 * end, where the extension is); a message longer than the whole line is shortened in its middle too. The tooltip always says the whole line.
 */
public final class StatusLine extends JPanel {
    private static final int GAP = 16;
    /** Narrower than this a shortened board name says too little to be worth its place. */
    private static final int MIN_BOARD_WIDTH = 48;
    private static final int SHORT_BOARD_WIDTH = 160;
    private static final String ELLIPSIS = "\u2026";

    private final JLabel board = label("status.board");
    private final JLabel state = label("status.state");
    private final JLabel time = label("status.time");
    private final JLabel fps = label("status.fps");
    private final JLabel message = label("status.message");
    private String boardName = "";
    private String messageText = " ";

    public StatusLine() {
        super(null);
        setBorder(BorderFactory.createEmptyBorder(3, 8, 3, 8));
        Font fixed = new Font(Font.MONOSPACED, Font.PLAIN, message.getFont().getSize());
        time.setFont(fixed);
        fps.setFont(fixed);
        for (JLabel label : new JLabel[] {board, state, time, fps, message}) {
            add(label);
        }
    }

    private static JLabel label(String name) {
        JLabel label = new JLabel();
        label.setName(name);
        return label;
    }

    /**
     * The facts of the moment; cheap when nothing changed (labels only repaint on a new text). The frame rate
     * is shown only while the game runs: stopped, or in build mode, it measures nothing worth reading.
     */
    public void show(String boardName, String mode, boolean running, String speed, double simulatedTime,
                     int framesPerSecond) {
        boolean changed = !boardName.equals(this.boardName);
        this.boardName = boardName;
        changed |= setText(state, mode + (running ? " - running" : " - stopped") + " at " + speed);
        changed |= setText(time, String.format(Locale.ROOT, "t = %.2f s", simulatedTime));
        changed |= setText(fps, running ? String.format(Locale.ROOT, "%3d fps", framesPerSecond) : "");
        if (changed) {
            textChanged();
        }
    }

    /** A message for the player (a refused edit, a saved file, an error), kept until the next one. */
    public void showMessage(String text) {
        if (!text.equals(messageText)) {
            messageText = text;
            textChanged();
        }
    }

    /** Whether {@code text} would show whole as the message, once the other facts have given way for it. */
    public boolean fitsWhole(String text) {
        Insets in = getInsets();
        int boardClaim = Math.min(fullBoardWidth(), SHORT_BOARD_WIDTH) + GAP;
        return message.getFontMetrics(message.getFont()).stringWidth(text)
                <= getWidth() - in.left - in.right - boardClaim;
    }

    public String message() {
        return messageText;
    }

    /** Everything the line says, in full, as one string (also its tooltip). */
    public String text() {
        return Stream.of(boardName, state.getText(), time.getText(), fps.getText(), messageText)
                .filter(s -> !s.isBlank()).collect(Collectors.joining("   "));
    }

    @Override
    public Dimension getPreferredSize() {
        if (isPreferredSizeSet()) {
            return super.getPreferredSize();
        }
        Insets in = getInsets();
        int width = in.left + in.right + messageWidth() + fullBoardWidth() + GAP;
        int height = Math.max(message.getPreferredSize().height, message.getFontMetrics(message.getFont()).getHeight());
        for (JLabel fact : List.of(board, state, time, fps)) {
            width += fact == board ? 0 : fact.getPreferredSize().width + GAP;
            height = Math.max(height, fact.getPreferredSize().height);
        }
        return new Dimension(width, height + in.top + in.bottom);
    }

    @Override
    public Dimension getMinimumSize() {
        Insets in = getInsets();
        return new Dimension(in.left + in.right, getPreferredSize().height);
    }

    /**
     * Decides first what shows and how (each label's text and visibility set once, so that laying out does
     * not invalidate the line again), then places the labels left to right.
     */
    @Override
    public void doLayout() {
        Insets in = getInsets();
        int width = getWidth() - in.left - in.right;
        int height = getHeight() - in.top - in.bottom;
        int messageWidth = messageWidth();
        // Lowest priority first: these give way, one by one, until the message fits.
        List<JLabel> shown = Stream.of(fps, time, state).filter(l -> !l.getText().isEmpty())
                .collect(Collectors.toList());
        int facts = shown.stream().mapToInt(l -> l.getPreferredSize().width + GAP).sum();
        int boardWidth = fullBoardWidth() + GAP;
        // A long name is shortened before any fact gives way, down to a width that still reads well.
        int boardClaim = Math.min(boardWidth, SHORT_BOARD_WIDTH + GAP);
        while (!shown.isEmpty() && boardClaim + facts + messageWidth > width) {
            facts -= shown.remove(0).getPreferredSize().width + GAP;
        }
        int boardRoom = width - messageWidth - facts - GAP;
        boolean boardShown = boardWidth + facts + messageWidth <= width || boardRoom >= MIN_BOARD_WIDTH;
        setText(board, boardShown ? middleEllipsis(boardName, board.getFontMetrics(board.getFont()), boardRoom)
                : boardName);
        board.setVisible(boardShown);
        for (JLabel l : List.of(fps, time, state)) {
            l.setVisible(shown.contains(l));
        }
        int x = in.left;
        for (JLabel fact : List.of(board, state, time, fps)) {
            if (fact.isVisible()) {
                int w = Math.min(fact.getPreferredSize().width, Math.max(0, in.left + width - x));
                fact.setBounds(x, in.top, w, height);
                x += w + GAP;
            }
        }
        int messageRoom = Math.max(0, in.left + width - x);
        // A message longer than the whole line loses its middle, not its end ("...without its 3 bad lines").
        setText(message, middleEllipsis(messageText, message.getFontMetrics(message.getFont()), messageRoom));
        message.setBounds(x, in.top, messageRoom, height);
    }

    private int fullBoardWidth() {
        return board.getFontMetrics(board.getFont()).stringWidth(boardName);
    }

    private int messageWidth() {
        return message.getFontMetrics(message.getFont()).stringWidth(messageText);
    }

    /**
     * {@code text} shortened in its middle to fit {@code width} pixels, keeping twice as much of its end (where
     * a file name has its extension and a message its outcome) as of its start: "a-ve…long-board.txt".
     */
    static String middleEllipsis(String text, FontMetrics metrics, int width) {
        if (metrics.stringWidth(text) <= width) {
            return text;
        }
        for (int keep = text.length() - 1; keep > 0; keep--) {
            int back = 2 * keep / 3;
            String shortened = text.substring(0, keep - back) + ELLIPSIS + text.substring(text.length() - back);
            if (metrics.stringWidth(shortened) <= width) {
                return shortened;
            }
        }
        return ELLIPSIS;
    }

    private void textChanged() {
        setToolTipText(text());
        revalidate();
        repaint();
    }

    private static boolean setText(JLabel label, String text) {
        if (text.equals(label.getText())) {
            return false;
        }
        label.setText(text);
        return true;
    }
}
