package gizmoball.view.editor;

import gizmoball.boardfile.KeyCodes;
import gizmoball.editor.Editor;
import gizmoball.editor.Tool;

import javax.swing.BorderFactory;
import javax.swing.Box;
import javax.swing.BoxLayout;
import javax.swing.ButtonGroup;
import javax.swing.JPanel;
import javax.swing.JToggleButton;
import javax.swing.SwingConstants;
import java.awt.BorderLayout;
import java.awt.GridLayout;
import java.awt.Insets;
import java.util.EnumMap;
import java.util.Map;

/**
 * The tool palette (west side in build mode): one toggle button per tool with its icon and a tooltip naming the
 * shortcut key and what to do. The placing tools are a grid of icons (each icon is what it places); the tools that
 * act on what is there (select, rotate, delete, connect...) are a labelled column, their icons being symbols. Both
 * fit the window the game opens in, so no tool is ever below a scroll fold at that size. The buttons do not take
 * focus, so keys keep going to the board.
 */
public final class PalettePanel extends JPanel {
    /** Icons a row: four keeps the grid no wider than the labelled column. */
    private static final int GRID_COLUMNS = 4;
    private static final int GAP = 2;
    /** Tight margins: the compact palette's icons, four to a row, leave a 700 px window its 240 px board. */
    private static final Insets ICON_MARGIN = new Insets(1, 1, 1, 1);
    private static final Insets LABEL_MARGIN = new Insets(1, 4, 1, 4);

    private final Map<Tool, JToggleButton> buttons = new EnumMap<>(Tool.class);
    private final JPanel acting = new JPanel(column());
    private final int labelledHeight;
    private boolean compact;

    private PalettePanel(Editor controller) {
        super(new BorderLayout());
        setBorder(BorderFactory.createEmptyBorder(6, 6, 6, 6));
        JPanel placing = new JPanel(new GridLayout(0, GRID_COLUMNS, GAP, GAP));
        JPanel stack = new JPanel();
        stack.setLayout(new BoxLayout(stack, BoxLayout.Y_AXIS));
        stack.add(placing);
        stack.add(Box.createVerticalStrut(8));
        stack.add(acting);
        // The buttons keep their natural height at the top however tall the window is.
        add(stack, BorderLayout.NORTH);
        ButtonGroup group = new ButtonGroup();
        for (Tool tool : Tool.values()) {
            boolean places = places(tool);
            JToggleButton button = new JToggleButton(places ? null : label(tool), new ToolIcon(tool));
            button.setName("tool." + tool.name());
            button.setHorizontalAlignment(places ? SwingConstants.CENTER : SwingConstants.LEADING);
            button.setMargin(places ? ICON_MARGIN : LABEL_MARGIN);
            button.setIconTextGap(8);
            button.setFocusable(false);
            button.setToolTipText("<html><b>" + tool.labelWithShortcut() + "</b><br>" + tool.hint() + "</html>");
            button.addActionListener(e -> controller.setTool(tool));
            group.add(button);
            (places ? placing : acting).add(button);
            buttons.put(tool, button);
        }
        buttons.get(controller.tool()).setSelected(true);
        labelledHeight = getPreferredSize().height;
    }

    /** The palette of {@code controller}'s tools, its buttons following the tool chosen (by key or click). */
    public static PalettePanel of(Editor controller) {
        PalettePanel palette = new PalettePanel(controller);
        controller.addStateListener(() -> palette.buttons.get(controller.tool()).setSelected(true));
        return palette;
    }

    /**
     * A compact palette shows the acting tools as icons too, in the placing tools' grid (each button's tooltip
     * still names the tool and its key), for windows too small for the labelled column.
     */
    public void setCompact(boolean compact) {
        if (compact == this.compact) {
            return;
        }
        this.compact = compact;
        acting.setLayout(compact ? new GridLayout(0, GRID_COLUMNS, GAP, GAP) : column());
        buttons.forEach((tool, button) -> {
            if (!places(tool)) {
                button.setText(compact ? null : label(tool));
                button.setHorizontalAlignment(compact ? SwingConstants.CENTER : SwingConstants.LEADING);
                button.setMargin(compact ? ICON_MARGIN : LABEL_MARGIN);
            }
        });
        revalidate();
        repaint();
    }

    /** The height of the palette with the labelled column: a side less tall than this takes the compact one. */
    public int labelledHeight() {
        return labelledHeight;
    }

    private static GridLayout column() {
        return new GridLayout(0, 1, 0, GAP);
    }

    /** A tool that puts something new on the board (a gizmo or a ball): its icon shows what. */
    private static boolean places(Tool tool) {
        return tool.kind().isPresent() || tool == Tool.BALL;
    }

    /** The tool's name, then its shortcut key greyed, so the keys are learnt by looking at the palette. */
    private static String label(Tool tool) {
        // nobr: a label laid out once at a narrower width (the compact palette) must not keep two lines' height.
        return "<html><nobr>" + tool.label() + " <font color=gray>" + KeyCodes.name(tool.shortcut())
                + "</font></nobr></html>";
    }
}
