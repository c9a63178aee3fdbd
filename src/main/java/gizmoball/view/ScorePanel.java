package gizmoball.view;

import gizmoball.model.Board;
import gizmoball.model.game.GameProgress;
import java.awt.Color;
import java.awt.Dimension;
import java.awt.Font;
import java.awt.FontMetrics;
import java.awt.Graphics;
import java.awt.Graphics2D;
import java.awt.RenderingHints;
import java.text.NumberFormat;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.Optional;
import java.util.stream.Collectors;
import javax.swing.JComponent;

/**
 * The strip above the board: score (in a game of several players each one's, "> " before the player whose ball is in
 * play), balls left (the player's own), the board's best (a sandbox says so instead of balls), and what is on (a
 * replay being watched, game over, a tilt). Its three cells share the width equally and the text takes the largest font
 * that fits them, so it stays readable in a narrow window and does not shout in a wide one.
 */
public final class ScorePanel extends JComponent {
    private static final Color BACKGROUND = new Color(0x1b, 0x1f, 0x2a);
    private static final Color LABEL = new Color(0x9a, 0xa3, 0xb5);
    private static final Color VALUE = new Color(0xf4, 0xf1, 0xe6);
    private static final Color NOTICE = new Color(0xff, 0xc8, 0x4a);
    private static final int HEIGHT = 40;
    private static final float LARGEST = 22f;
    private static final float SMALLEST = 9f;

    private final transient Board board;
    private String best = "-";
    private String notice = "";

    private ScorePanel(Board board) {
        this.board = board;
        setName("score.panel");
        setOpaque(true);
        setPreferredSize(new Dimension(300, HEIGHT));
        setMinimumSize(new Dimension(60, HEIGHT));
    }

    /** A panel on {@code board}, repainted on its every change. */
    public static ScorePanel of(Board board) {
        ScorePanel panel = new ScorePanel(board);
        board.addObserver((b, change) -> panel.repaint());
        return panel;
    }

    /** The board's best as the third cell shows it: "5,000 Ann", or nothing yet. */
    public void setBest(Optional<String> name, long score) {
        best = name.map(n -> format(score) + " " + n).orElse("-");
        repaint();
    }

    public void clearBest() {
        best = "-";
        repaint();
    }

    /** What is going on, in a cell of its own (empty for nothing): "Watching Ann's 5,000". */
    public void setNotice(String text) {
        notice = text;
        repaint();
    }

    /** The cells as they read now, label and value (the notice's label is empty), for painting and the tests. */
    public List<Cell> cells() {
        GameProgress game = board.game();
        List<Cell> cells = new ArrayList<>();
        if (game.players() == 1) {
            cells.add(new Cell("Score ", format(game.score())));
        } else {
            for (int p = 0; p < game.players(); p++) {
                boolean up = p == game.currentPlayer() && !game.isOver();
                cells.add(new Cell((up ? "> " : "") + "P" + (p + 1) + " ", format(game.score(p))));
            }
        }
        int balls = game.players() == 1 ? game.ballsLeft() : game.ballsLeft(game.currentPlayer());
        cells.add(!game.isGame() ? new Cell("", "Sandbox") : game.isOver() ? new Cell("", "Game over")
                : game.isTilted() ? new Cell("", "TILT") : new Cell("Balls ", Integer.toString(balls)));
        cells.add(new Cell("Best ", best));
        if (!notice.isEmpty()) {
            cells.add(new Cell("", notice));
        }
        return cells;
    }

    /** One cell: a label in grey, a value in white. */
    public record Cell(String label, String value) {
        String text() {
            return label + value;
        }
    }

    private static String format(long n) {
        return NumberFormat.getIntegerInstance(Locale.ROOT).format(n);
    }

    @Override
    protected void paintComponent(Graphics graphics) {
        Graphics2D g = (Graphics2D) graphics.create();
        try {
            g.setRenderingHint(RenderingHints.KEY_TEXT_ANTIALIASING, RenderingHints.VALUE_TEXT_ANTIALIAS_ON);
            g.setColor(BACKGROUND);
            g.fillRect(0, 0, getWidth(), getHeight());
            List<Cell> cells = cells();
            int cell = getWidth() / cells.size();
            g.setFont(fitting(g, cells, cell - 12));
            FontMetrics m = g.getFontMetrics();
            int baseline = (getHeight() - m.getHeight()) / 2 + m.getAscent();
            for (int i = 0; i < cells.size(); i++) {
                Cell c = cells.get(i);
                int x = i * cell + (cell - m.stringWidth(c.text())) / 2;
                g.setColor(LABEL);
                g.drawString(c.label(), x, baseline);
                // A cell without a label is news (the game is over, a tilt, a replay is on), and so is whose turn it is.
                g.setColor(c.label().isEmpty() && board.game().isGame() || c.label().startsWith("> ")
                        || i == cells.size() - 1 && !notice.isEmpty() ? NOTICE : VALUE);
                g.drawString(c.value(), x + m.stringWidth(c.label()), baseline);
            }
            setToolTipText(cells.stream().map(Cell::text).collect(Collectors.joining("   ")));
        } finally {
            g.dispose();
        }
    }

    private Font fitting(Graphics2D g, List<Cell> cells, int width) {
        Font font = getFont() == null ? new Font(Font.SANS_SERIF, Font.BOLD, 12) : getFont();
        for (float size = LARGEST; ; size -= 1) {
            Font candidate = font.deriveFont(Font.BOLD, size);
            FontMetrics m = g.getFontMetrics(candidate);
            if (size <= SMALLEST || m.getHeight() <= getHeight() - 4
                    && cells.stream().allMatch(c -> m.stringWidth(c.text()) <= width)) {
                return candidate;
            }
        }
    }
}
