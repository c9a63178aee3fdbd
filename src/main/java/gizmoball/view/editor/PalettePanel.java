package gizmoball.view.editor;

import gizmoball.boardfile.KeyCodes;
import gizmoball.editor.Editor;
import gizmoball.editor.Tool;

import javax.swing.BorderFactory;
import javax.swing.ButtonGroup;
import javax.swing.JPanel;
import javax.swing.JToggleButton;
import javax.swing.SwingConstants;
import java.awt.BorderLayout;
import java.awt.GridLayout;
import java.util.EnumMap;
import java.util.Map;

/**
 * The tool palette (west side in build mode): one toggle button per tool with its icon, label, and a tooltip
 * naming the shortcut key and what to do. The buttons do not take focus, so keys keep going to the board.
 */
public final class PalettePanel extends JPanel {
    private final Map<Tool, JToggleButton> buttons = new EnumMap<>(Tool.class);
    private final JPanel column = new JPanel(new GridLayout(0, 1, 0, 2));
    private boolean compact;

    private PalettePanel(Editor controller) {
        super(new BorderLayout());
        setBorder(BorderFactory.createEmptyBorder(6, 6, 6, 6));
        // The buttons keep their natural height at the top however tall the window is.
        add(column, BorderLayout.NORTH);
        ButtonGroup group = new ButtonGroup();
        for (Tool tool : Tool.values()) {
            JToggleButton button = new JToggleButton(label(tool), new ToolIcon(tool));
            button.setName("tool." + tool.name());
            button.setHorizontalAlignment(SwingConstants.LEADING);
            button.setIconTextGap(8);
            button.setFocusable(false);
            button.setToolTipText("<html><b>" + tool.labelWithShortcut() + "</b><br>" + tool.hint() + "</html>");
            button.addActionListener(e -> controller.setTool(tool));
            group.add(button);
            column.add(button);
            buttons.put(tool, button);
        }
        buttons.get(controller.tool()).setSelected(true);
    }

    /** The palette of {@code controller}'s tools, its buttons following the tool chosen (by key or click). */
    public static PalettePanel of(Editor controller) {
        PalettePanel palette = new PalettePanel(controller);
        controller.addStateListener(() -> palette.buttons.get(controller.tool()).setSelected(true));
        return palette;
    }

    /**
     * A compact palette is a grid of icons, two to a row (each button's tooltip still names the tool and its key),
     * for windows too narrow to give the board its room beside the labelled column.
     */
    public void setCompact(boolean compact) {
        if (compact == this.compact) {
            return;
        }
        this.compact = compact;
        column.setLayout(new GridLayout(0, compact ? 2 : 1, 2, 2));
        buttons.forEach((tool, button) -> button.setText(compact ? null : label(tool)));
        revalidate();
        repaint();
    }

    /** The tool's name, then its shortcut key greyed, so the keys are learnt by looking at the palette. */
    private static String label(Tool tool) {
        // nobr: a label laid out once at a narrower width (the compact palette) must not keep two lines' height.
        return "<html><nobr>" + tool.label() + " <font color=gray>" + KeyCodes.name(tool.shortcut())
                + "</font></nobr></html>";
    }
}
