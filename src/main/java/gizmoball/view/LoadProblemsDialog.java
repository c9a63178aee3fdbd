package gizmoball.view;

import java.awt.BorderLayout;
import java.awt.Component;
import java.awt.FlowLayout;
import java.awt.Dimension;
import java.awt.Insets;
import java.awt.Window;
import java.util.List;
import javax.swing.BorderFactory;
import javax.swing.BoxLayout;
import javax.swing.DefaultListCellRenderer;
import javax.swing.JButton;
import javax.swing.JDialog;
import javax.swing.JLabel;
import javax.swing.JList;
import javax.swing.JPanel;
import javax.swing.JScrollPane;
import javax.swing.ScrollPaneConstants;
import javax.swing.SwingUtilities;

/**
 * Tells the player why a board file could not be loaded, line by line, and asks whether to load it
 * without those lines or to keep the board shown now. Under their own heading it lists the notes: lines that
 * load, read in a way worth knowing (written in another implementation's way, a ball placed on another). A file
 * with notes only loads as it is; the dialog then just reports them. Each list is as tall as its lines (up to
 * {@link #MOST_ROWS}), the problems first, and a long reason wraps under its line rather than running off the side.
 */
public final class LoadProblemsDialog extends JDialog {
    public static final String SKIP = "Load skipping these lines";
    public static final String KEEP = "Keep current board";
    public static final String OK = "OK";
    private static final int MOST_ROWS = 12;
    /** Pixels a line's text wraps at. */
    private static final int WRAP = 720;
    /** Between a line of the file and why, in each entry given: the dialog shows the reason under its line. */
    public static final String BECAUSE = "   <- ";

    private boolean skip;

    private LoadProblemsDialog(Component parent, String fileName, List<String> problems, List<String> notes,
                               boolean skippable) {
        super(parent instanceof Window w ? w : SwingUtilities.getWindowAncestor(parent),
                (problems.isEmpty() ? "Notes on " : "Problems in ") + fileName, ModalityType.APPLICATION_MODAL);
        setName("loadProblems");
        JPanel sections = new JPanel();
        sections.setLayout(new BoxLayout(sections, BoxLayout.Y_AXIS));
        if (!problems.isEmpty()) {
            sections.add(section(!skippable
                    ? "Nothing in " + fileName + " can be loaded:"
                    : problems.size() == 1
                    ? fileName + " has a line that cannot be loaded:"
                    : fileName + " has " + problems.size() + " lines that cannot be loaded:", problems, "loadProblems"));
        }
        if (!notes.isEmpty()) {
            sections.add(section(notes.size() == 1 ? "A note on a line that loads:"
                    : notes.size() + " notes on lines that load:", notes, "loadProblems.notes"));
        }
        JPanel buttons = new JPanel(new FlowLayout(FlowLayout.RIGHT));
        JButton close;
        if (problems.isEmpty()) {
            close = button(OK, false);
        } else {
            if (skippable) {
                buttons.add(button(SKIP, true));
            }
            close = button(KEEP, false);
        }
        buttons.add(close);
        add(sections, BorderLayout.CENTER);
        add(buttons, BorderLayout.SOUTH);
        getRootPane().setDefaultButton(close);
        setDefaultCloseOperation(DISPOSE_ON_CLOSE);
        EscapeCloses.install(this);
        pack();
        setLocationRelativeTo(parent);
    }

    /** A heading over its list of lines; the list is named {@code name}.list. */
    private static JPanel section(String heading, List<String> lines, String name) {
        JLabel label = new JLabel(heading);
        label.setName(name + ".heading");
        label.setBorder(BorderFactory.createEmptyBorder(8, 8, 8, 8));
        JList<String> list = new JList<>(lines.toArray(String[]::new));
        list.setName(name + ".list");
        list.setCellRenderer(new Wrapped());
        JScrollPane scroll = new JScrollPane(list, ScrollPaneConstants.VERTICAL_SCROLLBAR_AS_NEEDED,
                ScrollPaneConstants.HORIZONTAL_SCROLLBAR_NEVER);
        // As tall as its first MOST_ROWS lines, each as tall as it wraps to.
        int height = 0;
        for (int i = 0; i < Math.min(MOST_ROWS, lines.size()); i++) {
            height += list.getCellRenderer().getListCellRendererComponent(list, lines.get(i), i, false, false)
                    .getPreferredSize().height;
        }
        Insets in = scroll.getInsets();
        int width = list.getPreferredSize().width + scroll.getVerticalScrollBar().getPreferredSize().width;
        scroll.setPreferredSize(new Dimension(width + in.left + in.right, height + in.top + in.bottom));
        JPanel section = new JPanel(new BorderLayout());
        section.add(label, BorderLayout.NORTH);
        section.add(scroll, BorderLayout.CENTER);
        return section;
    }

    /** A line of the file in a fixed font, and why under it, indented, wrapping at {@link #WRAP} pixels. */
    private static final class Wrapped extends DefaultListCellRenderer {
        private static final long serialVersionUID = 1L;

        @Override
        public Component getListCellRendererComponent(JList<?> list, Object value, int index, boolean selected,
                                                      boolean focused) {
            String text = String.valueOf(value);
            int because = text.indexOf(BECAUSE);
            String line = because < 0 ? text : text.substring(0, because);
            String why = because < 0 ? "" : text.substring(because + BECAUSE.length());
            String html = "<html><body style='width: " + WRAP + "px'><tt>" + escape(line) + "</tt>"
                    + (why.isEmpty() ? "" : "<div style='margin-left: 24px'>" + escape(why) + "</div>")
                    + "</body></html>";
            super.getListCellRendererComponent(list, html, index, selected, focused);
            setBorder(BorderFactory.createEmptyBorder(2, 4, 2, 4));
            return this;
        }

        private static String escape(String text) {
            return text.replace("&", "&amp;").replace("<", "&lt;").replace(">", "&gt;");
        }
    }

    private JButton button(String text, boolean skipLines) {
        JButton button = new JButton(text);
        button.addActionListener(e -> close(skipLines));
        return button;
    }

    /**
     * Blocks (modal) until the player chooses; true to load skipping the lines. Closing the dialog keeps the
     * board. Unless {@code skippable} (skipping would leave nothing), keeping the board is the only choice.
     * The notes are listed under their own heading.
     */
    public static boolean askSkip(Component parent, String fileName, List<String> problems, List<String> notes,
                                  boolean skippable) {
        LoadProblemsDialog dialog = new LoadProblemsDialog(parent, fileName, problems, notes, skippable);
        dialog.setVisible(true);
        return dialog.skip;
    }

    /** Blocks (modal) until the player has read the notes of a file that loaded. */
    public static void showNotes(Component parent, String fileName, List<String> notes) {
        new LoadProblemsDialog(parent, fileName, List.of(), notes, false).setVisible(true);
    }

    private void close(boolean skipLines) {
        skip = skipLines;
        dispose();
    }
}
