package gizmoball.view.editor;

import gizmoball.boardfile.KeyCodes;
import gizmoball.editor.Editor;
import gizmoball.editor.Tool;

import javax.swing.AbstractButton;
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

    public PalettePanel(Editor controller) {
        super(new BorderLayout());
        setBorder(BorderFactory.createEmptyBorder(6, 6, 6, 6));
        // The buttons keep their natural height at the top however tall the window is.
        JPanel column = new JPanel(new GridLayout(0, 1, 0, 2));
        add(column, BorderLayout.NORTH);
        ButtonGroup group = new ButtonGroup();
        for (Tool tool : Tool.values()) {
            // The shortcut key, greyed after the label, so the keys are learnt by looking at the palette.
            JToggleButton button = new JToggleButton("<html>" + tool.label() + " <font color=gray>"
                    + KeyCodes.name(tool.shortcut()) + "</font></html>", new ToolIcon(tool));
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
        controller.addStateListener(() -> buttons.get(controller.tool()).setSelected(true));
        buttons.get(controller.tool()).setSelected(true);
    }

    /** The button of a tool (for tests and for the installer's focus handling). */
    public AbstractButton button(Tool tool) {
        return buttons.get(tool);
    }
}
