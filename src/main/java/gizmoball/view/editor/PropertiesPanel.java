package gizmoball.view.editor;

import static gizmoball.view.editor.PanelFields.constraints;
import static gizmoball.view.editor.PanelFields.enableAll;
import static gizmoball.view.editor.PanelFields.row;
import static gizmoball.view.editor.PanelFields.wide;

import gizmoball.editor.Editor;
import gizmoball.model.Board;
import gizmoball.model.BoardChange;
import gizmoball.model.game.Points;
import gizmoball.model.gizmo.Gizmo;
import gizmoball.model.gizmo.Setting;
import gizmoball.model.loop.BallView;
import gizmoball.model.loop.TriggerSource;

import javax.swing.BorderFactory;
import javax.swing.JCheckBox;
import javax.swing.JComponent;
import javax.swing.JLabel;
import javax.swing.JPanel;
import javax.swing.JTextField;
import javax.swing.SwingConstants;
import java.awt.BorderLayout;
import java.awt.Dimension;
import java.awt.GridBagConstraints;
import java.awt.GridBagLayout;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Objects;
import java.util.Optional;

/**
 * Build mode's east panel: the board's gravity and friction and its game (balls a game, the extra-ball score), and
 * the selection: its name and place, a ball's position and velocity, a gizmo's colour and points (and whether an
 * absorber is a drain), connections and key bindings (each removable). Numbers are read here,
 * with the board file's grammar ({@link NumberField}); the editor applies them or reports why not, and reads a
 * colour's #rrggbb itself. Enter or Apply applies a group of fields, Esc puts back the board's values; both hand
 * the keyboard back to the board, so the next key is a tool key again, not more text.
 * <p>
 * The board's section and the selection's are two {@link PanelTabs}, the selection's brought forward by a new
 * selection. Each section that stands alone is a class of its own: the {@link BoardSection}, the {@link BallRows}, the
 * {@link ColourRows}, an absorber's {@link PlungerRow}, the {@link LinksSection}; what they do alike with fields is
 * {@link PanelFields}'. Just over 400 lines because the selection's own rows (its description, name and cell,
 * points and a kind's setting) share one grid and one refresh here.
 */
public final class PropertiesPanel extends JPanel {
    private static final int WIDTH = 250;
    private static final int SELECTION_WIDTH = 226;

    private final Editor controller;
    private final Runnable focusBoard;
    private final PanelFields fields;
    private final BoardSection boardSection;
    private final PlungerRow plungerRow;
    private final NumberField points = new NumberField("gizmo.points");
    private final JCheckBox drain = new JCheckBox("Drain: its balls are lost");
    private final NumberField factor = new NumberField("gizmo.factor");
    private final JTextField pair = new JTextField(5);
    private final JPanel factorPart = new JPanel(new BorderLayout(4, 0));
    private final NumberField speed = new NumberField("gizmo.speed");
    private final JPanel speedPart = new JPanel(new BorderLayout(4, 0));
    private final JLabel selection = new JLabel();
    private final JTextField name = new JTextField(7);
    private final NumberField cellX = new NumberField("gizmo.x");
    private final NumberField cellY = new NumberField("gizmo.y");
    private final JPanel nameRows = new JPanel(new GridBagLayout());
    private final BallRows ballRows;
    private final ColourRows colourRows;
    private final LinksSection linksSection;
    private final PanelTabs tabs;
    private String shownSelection;
    private List<String> shownGroup = List.of();

    private PropertiesPanel(Editor controller, Runnable focusBoard) {
        this.controller = controller;
        this.focusBoard = focusBoard;
        fields = new PanelFields(controller, focusBoard, this::refresh);
        boardSection = new BoardSection(controller, fields);
        plungerRow = new PlungerRow(controller, fields);
        ballRows = new BallRows(controller, fields);
        linksSection = new LinksSection(controller);
        colourRows = new ColourRows(controller, fields);
        setLayout(new BorderLayout());
        setBorder(BorderFactory.createEmptyBorder(6, 6, 6, 6));
        // At the top at its natural height, however tall the window is; the tab follows the selection (refresh).
        tabs = new PanelTabs(boardSection.component(), selectionSection());
        add(tabs, BorderLayout.NORTH);

        refresh();
    }

    /**
     * The panel of {@code controller}'s board and selection, following its edits and selection.
     *
     * @param focusBoard gives the keyboard back to the board view (after Enter, Apply or Esc in a field)
     */
    public static PropertiesPanel of(Editor controller, Runnable focusBoard) {
        PropertiesPanel panel = new PropertiesPanel(controller, focusBoard);
        controller.board().addObserver((board, change) -> {
            if (change != BoardChange.TICK) {
                panel.refresh();
            }
        });
        controller.addStateListener(() -> {
            if (!Objects.equals(controller.selected().orElse(null), panel.shownSelection)
                    || !controller.selection().equals(panel.shownGroup)) {
                panel.refresh();
            }
        });
        return panel;
    }

    /** A fixed width: the board view must not jump when the selection shows more or fewer rows. */
    @Override
    public Dimension getPreferredSize() {
        return new Dimension(WIDTH, super.getPreferredSize().height);
    }

    /** Shows the board's current values; called on edits and selection changes, not on every pointer move. */
    public void refresh() {
        Board board = controller.board();
        boardSection.show(board);

        String selectedBefore = shownSelection;
        List<String> groupBefore = shownGroup;
        shownSelection = controller.selected().orElse(null);
        shownGroup = controller.selection();
        // What was just clicked is what one means to edit; an edit (the same selection) leaves the tab one chose.
        if (!Objects.equals(shownSelection, selectedBefore) || !shownGroup.equals(groupBefore)) {
            tabs.showSelection(shownSelection != null || !shownGroup.isEmpty());
        }
        // Of several selected, nothing one of them alone has is shown: an edit here would seem to apply to all.
        boolean several = shownGroup.size() > 1;
        Optional<Gizmo> gizmo = several ? Optional.empty() : controller.selectedGizmo();
        Optional<BallView> ball = several ? Optional.empty() : controller.selectedBall();
        selection.setText(several ? describe(shownGroup) : describe(gizmo, ball));
        // The ball's and the colour's rows keep their room when they do not apply, so that nothing below jumps.
        Setting setting = gizmo.map(Gizmo::setting).orElse(new Setting.None());
        ballRows.show(ball, as(setting, Setting.Launch.class));
        enableAll(nameRows, gizmo.isPresent() || ball.isPresent());
        name.setText(gizmo.map(Gizmo::name).or(() -> ball.map(BallView::name)).orElse(""));
        RefusedValue.unmark(name);
        cellX.setEnabled(gizmo.isPresent());
        cellY.setEnabled(gizmo.isPresent());
        cellX.setText(gizmo.map(g -> Integer.toString(g.x())).orElse(""));
        cellY.setText(gizmo.map(g -> Integer.toString(g.y())).orElse(""));
        RefusedValue.unmark(cellX);
        RefusedValue.unmark(cellY);
        colourRows.show(gizmo);
        points.setEnabled(gizmo.isPresent());
        points.setText(gizmo.map(g -> Integer.toString(board.gameRules().pointsOf(g.name(), g.kind()))).orElse(""));
        RefusedValue.unmark(points);
        drain.setEnabled(gizmo.filter(g -> g.kind().canDrain()).isPresent());
        Optional<Setting.Factor> accelerator = as(setting, Setting.Factor.class);
        factor.setEnabled(accelerator.isPresent());
        factor.setText("");
        accelerator.ifPresent(a -> factor.show(a.factor()));
        RefusedValue.unmark(factor);
        Optional<Setting.Pair> portal = as(setting, Setting.Pair.class);
        pair.setEnabled(portal.isPresent());
        pair.setText(portal.flatMap(Setting.Pair::portal).orElse(""));
        RefusedValue.unmark(pair);
        Optional<Setting.Speed> spinner = as(setting, Setting.Speed.class);
        speed.setEnabled(spinner.isPresent());
        speed.setText("");
        spinner.ifPresent(s -> speed.show(s.turnsPerSecond()));
        RefusedValue.unmark(speed);
        factorPart.setVisible(spinner.isEmpty());
        speedPart.setVisible(spinner.isPresent());
        drain.setSelected(gizmo.filter(g -> board.gameRules().isDrain(g.name())).isPresent());
        plungerRow.show(as(setting, Setting.Pull.class));

        linksSection.show(board, several ? null : shownSelection);
    }

    /** The setting as its record, if it is one: each field of the panel shows the setting of one record. */
    private static <S extends Setting> Optional<S> as(Setting setting, Class<S> record) {
        return Optional.of(setting).filter(record::isInstance).map(record::cast);
    }

    private JComponent selectionSection() {
        JPanel p = new JPanel(new GridBagLayout());
        selection.setName("selection");
        // Two lines' room whatever is selected: a longer description must not push the rows below it down.
        selection.setVerticalAlignment(SwingConstants.TOP);
        Dimension twoLines = new Dimension(SELECTION_WIDTH,
                2 * selection.getFontMetrics(selection.getFont()).getHeight() + 4);
        selection.setPreferredSize(twoLines);
        selection.setMinimumSize(twoLines);
        GridBagConstraints c = constraints(0, 0);
        c.gridwidth = 2;
        p.add(selection, c);
        p.add(ballRows.component(), wide(constraints(0, 1)));

        p.add(colourRows.component(), wide(constraints(0, 2)));
        points.setToolTipText("What a real hit on the gizmo scores");
        points.addActionListener(e -> applyPoints());
        fields.restoreOnEscape(points);
        JPanel pointsRow = new JPanel(new GridBagLayout());
        factor.setToolTipText("An accelerator: how many times faster a ball leaves it, 1 to 5");
        factor.setColumns(3);
        factor.addActionListener(e -> applyFactor());
        fields.restoreOnEscape(factor);
        speed.setToolTipText("A spinner: turns a second, negative anticlockwise, up to 3 either way");
        speed.setColumns(3);
        speed.addActionListener(e -> applySpeed());
        fields.restoreOnEscape(speed);
        // One row for all, so that the panel is no taller for the accelerator's or the spinner's own value (the
        // spinner's speed takes the factor's place while a spinner is selected).
        JPanel pointsAndFactor = new JPanel(new BorderLayout(4, 0));
        factorPart.add(new JLabel("x"), BorderLayout.WEST);
        factorPart.add(factor, BorderLayout.CENTER);
        speedPart.add(speed, BorderLayout.CENTER);
        speedPart.add(new JLabel("turns/s"), BorderLayout.EAST);
        speedPart.setVisible(false);
        JPanel ownValue = new JPanel(new BorderLayout(0, 0));
        ownValue.add(factorPart, BorderLayout.WEST);
        ownValue.add(speedPart, BorderLayout.EAST);
        pointsAndFactor.add(points, BorderLayout.CENTER);
        pointsAndFactor.add(ownValue, BorderLayout.EAST);
        row(pointsRow, 0, "Points", pointsAndFactor);
        p.add(pointsRow, wide(constraints(0, 3)));
        drain.setName("gizmo.drain");
        drain.setToolTipText("A ball this absorber captures is lost to the game; the next one waits in it");
        drain.addActionListener(e -> controller.selectedGizmo().ifPresent(g -> {
            controller.properties().setDrain(g.name(), drain.isSelected());
            focusBoard.run();
        }));
        pair.setName("gizmo.pair");
        pair.setToolTipText("A portal: the portal a ball entering its mouth leaves by (empty: none, a wall)");
        pair.addActionListener(e -> applyPair());
        fields.restoreOnEscape(pair);
        JPanel absorberRows = new JPanel(new BorderLayout(0, 2));   // an absorber's game: drain, plunger
        absorberRows.add(drain, BorderLayout.NORTH);
        absorberRows.add(plungerRow.component(), BorderLayout.SOUTH);
        p.add(absorberRows, wide(constraints(0, 4)));
        p.add(nameRows(), wide(constraints(0, 5)));

        linksSection.addTo(p, 6);
        return p;
    }

    /** The keyboard to the selection's name field, all of it selected, to rename or read on from there. */
    public void focusName() {
        tabs.showSelection(true);
        name.requestFocusInWindow();
        name.selectAll();
    }

    /** The selection's name (Enter renames it) and a gizmo's cell (Enter moves it there). */
    private JComponent nameRows() {
        name.setName("selection.name");
        name.setToolTipText("Type a new name and press Enter: its connections and keys follow");
        name.addActionListener(e -> applyName());
        row(nameRows, 0, "Name", name);
        JPanel cell = new JPanel(new GridBagLayout());
        cellX.setColumns(3);
        cellY.setColumns(3);
        for (int i = 0; i < 2; i++) {
            GridBagConstraints half = constraints(i, 0);
            half.weightx = 1;
            cell.add(i == 0 ? cellX : cellY, half);
        }
        row(nameRows, 1, "Cell x, y", cell);
        row(nameRows, 2, "Pair", pair);   // a portal's: beside its name, the name of the portal it leads to
        for (NumberField f : new NumberField[] {cellX, cellY}) {
            f.setToolTipText("The gizmo's top-left cell; Enter moves it there");
            f.addActionListener(e -> applyCell());
            fields.restoreOnEscape(f);
        }
        return nameRows;
    }

    private void applyName() {
        Optional<String> selected = controller.selected().filter(n -> !controller.wallsSelected());
        String typed = name.getText();
        if (selected.isPresent()) {
            if (controller.properties().rename(selected.get(), typed)) {
                focusBoard.run();
            } else {
                fields.keepRefused(Map.of(name, typed));
            }
        }
    }

    private void applyCell() {
        Optional<Gizmo> gizmo = controller.selectedGizmo();
        Optional<double[]> v = fields.values(cellX, cellY);
        if (gizmo.isEmpty() || v.isEmpty()) {
            return;
        }
        double x = v.get()[0];
        double y = v.get()[1];
        if (x != Math.rint(x) || y != Math.rint(y) || Math.abs(x) > Board.SIZE || Math.abs(y) > Board.SIZE) {
            fields.refuse(x != Math.rint(x) || Math.abs(x) > Board.SIZE ? cellX : cellY,
                    "A cell is a whole number from 0 to " + (Board.SIZE - 1));
            return;
        }
        Map<JTextField, String> typed = new LinkedHashMap<>();
        typed.put(cellX, cellX.getText());
        typed.put(cellY, cellY.getText());
        if (controller.properties().moveGizmoTo(gizmo.get().name(), (int) x, (int) y)) {
            focusBoard.run();
        } else {
            fields.keepRefused(typed);
        }
    }


    private void applyFactor() {
        Optional<Gizmo> gizmo = controller.selectedGizmo();
        Optional<double[]> v = fields.values(factor);
        if (gizmo.isEmpty() || v.isEmpty()) {
            return;
        }
        String typed = factor.getText();
        if (controller.properties().set(gizmo.get().name(), new Setting.Factor(v.get()[0]))) {
            focusBoard.run();
        } else {
            fields.keepRefused(Map.of(factor, typed));
        }
    }

    private void applyPair() {
        Optional<Gizmo> gizmo = controller.selectedGizmo();
        if (gizmo.isEmpty()) {
            return;
        }
        String typed = pair.getText();
        if (controller.properties().set(gizmo.get().name(), Setting.Pair.with(typed.strip()))) {
            focusBoard.run();
        } else {
            fields.keepRefused(Map.of(pair, typed));
        }
    }

    private void applySpeed() {
        Optional<Gizmo> gizmo = controller.selectedGizmo();
        Optional<double[]> v = fields.values(speed);
        if (gizmo.isEmpty() || v.isEmpty()) {
            return;
        }
        String typed = speed.getText();
        if (controller.properties().set(gizmo.get().name(), new Setting.Speed(v.get()[0]))) {
            focusBoard.run();
        } else {
            fields.keepRefused(Map.of(speed, typed));
        }
    }

    private void applyPoints() {
        Optional<Gizmo> gizmo = controller.selectedGizmo();
        Optional<double[]> v = fields.values(points);
        if (gizmo.isEmpty() || v.isEmpty()) {
            return;
        }
        double value = v.get()[0];
        if (value != Math.rint(value) || Math.abs(value) > Points.LIMIT) {
            fields.refuse(points, "Points: a whole number from -" + Points.LIMIT + " to " + Points.LIMIT);
            return;
        }
        String typed = points.getText();
        if (controller.properties().setPoints(gizmo.get().name(), (int) value)) {
            focusBoard.run();
        } else {
            fields.keepRefused(Map.of(points, typed));
        }
    }

    private String describe(Optional<Gizmo> gizmo, Optional<BallView> ball) {
        if (gizmo.isPresent()) {
            Gizmo g = gizmo.get();
            return named(g.name(), g.kind().displayName() + " " + g.width() + "x" + g.height() + " at (" + g.x()
                    + "," + g.y() + ")" + (g.rotation() == 0 ? "" : ", " + g.rotation() * 90 + "\u00b0"));
        }
        if (ball.isPresent()) {
            BallView b = ball.get();
            return named(b.name(), "ball" + (b.isCaptured() ? " (held by an absorber)" : ""));
        }
        return controller.wallsSelected()
                ? named(TriggerSource.OUTER_WALLS.name(), "the walls around the board")
                : "Nothing selected";
    }

    /** Several selected: how many, and which (the first few). */
    /**
     * "5 selected: S1, S2, T1 and 2 more (Shift+click takes one out)": as many names as the label's two lines hold,
     * and how many more, so that no name is cut.
     */
    private String describe(List<String> group) {
        for (int shown = group.size(); ; shown--) {
            String names = String.join(", ", group.subList(0, shown))
                    + (shown == group.size() ? "" : (shown == 0 ? "" : " and ") + (group.size() - shown) + " more");
            String text = named(group.size() + " selected", names + " (Shift+click takes one out)");
            if (shown == 0 || fitsTheLabel(text)) {
                return text;
            }
        }
    }

    private boolean fitsTheLabel(String text) {
        JLabel probe = new JLabel(text);
        probe.setFont(selection.getFont());
        return probe.getPreferredSize().height <= selection.getPreferredSize().height;
    }

    /** "<b>name</b>: what", wrapped within the label's width. */
    private static String named(String name, String what) {
        return "<html><body style='width: " + (SELECTION_WIDTH - 10) + "px'><b>" + name + "</b>: " + what
                + "</body></html>";
    }

}
