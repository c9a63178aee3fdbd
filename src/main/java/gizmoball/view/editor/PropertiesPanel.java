package gizmoball.view.editor;

import gizmoball.boardfile.Decimals;
import gizmoball.boardfile.KeyCodes;
import gizmoball.boardfile.OrderWords;
import gizmoball.editor.Editor;
import gizmoball.editor.PropertyEdits;
import gizmoball.model.Board;
import gizmoball.model.BoardChange;
import gizmoball.model.KeyBinding;
import gizmoball.model.game.GameRules;
import gizmoball.model.game.Points;
import gizmoball.model.gizmo.Gizmo;
import gizmoball.model.gizmo.Plunger;
import gizmoball.model.gizmo.Rgb;
import gizmoball.model.gizmo.Setting;
import gizmoball.model.loop.BallView;
import gizmoball.model.loop.Connection;
import gizmoball.model.loop.TriggerSource;
import gizmoball.view.BoardPainter;

import javax.swing.BorderFactory;
import javax.swing.Box;
import javax.swing.BoxLayout;
import javax.swing.DefaultListModel;
import javax.swing.JButton;
import javax.swing.JCheckBox;
import javax.swing.JColorChooser;
import javax.swing.JComponent;
import javax.swing.JLabel;
import javax.swing.JList;
import javax.swing.JPanel;
import javax.swing.JScrollPane;
import javax.swing.JTextField;
import javax.swing.ListSelectionModel;
import javax.swing.SwingConstants;
import javax.swing.SwingUtilities;
import java.awt.BorderLayout;
import java.awt.Component;
import java.awt.Container;
import java.awt.Color;
import java.awt.Dimension;
import java.awt.FlowLayout;
import java.awt.GridBagConstraints;
import java.awt.GridBagLayout;
import java.awt.Insets;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Objects;
import java.awt.event.ActionEvent;
import java.awt.event.KeyEvent;
import java.util.Optional;
import java.util.OptionalDouble;
import java.util.OptionalLong;
import javax.swing.AbstractAction;
import javax.swing.KeyStroke;

/**
 * Build mode's east panel: the board's gravity and friction and its game (balls a game, the extra-ball score), and
 * the selection: its name and place, a ball's position and velocity, a gizmo's colour and points (and whether an
 * absorber is a drain), connections and key bindings (each removable). Numbers are read here,
 * with the board file's grammar ({@link NumberField}); the editor applies them or reports why not, and reads a
 * colour's #rrggbb itself. Enter or Apply applies a group of fields, Esc puts back the board's values; both hand
 * the keyboard back to the board, so the next key is a tool key again, not more text.
 */
public final class PropertiesPanel extends JPanel {
    /** One line of the links list, with what removing it means. */
    private record Link(String text, Runnable remove) {
        @Override
        public String toString() {
            return text;
        }
    }

    private static final int WIDTH = 250;
    private static final int SELECTION_WIDTH = 226;

    private final Editor controller;
    private final Runnable focusBoard;
    private final NumberField gravity = new NumberField("gravity");
    private final NumberField mu = new NumberField("mu");
    private final NumberField mu2 = new NumberField("mu2");
    private final NumberField balls = new NumberField("game.balls");
    private final JTextField extraBall = new JTextField(7);
    private final JTextField nudgeSpeed = new JTextField(7);
    private final NumberField tiltNudges = new NumberField("game.tilt.nudges");
    private final NumberField tiltSeconds = new NumberField("game.tilt.seconds");
    private final NumberField ballSave = new NumberField("game.ballsave");
    private final NumberField points = new NumberField("gizmo.points");
    private final JCheckBox drain = new JCheckBox("Drain: its balls are lost");
    private final JCheckBox plunger = new JCheckBox("Plunger");
    private final NumberField plungerSpeed = new NumberField("gizmo.plunger.speed");
    private final NumberField plungerSeconds = new NumberField("gizmo.plunger.seconds");
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
    private final NumberField ballX = new NumberField("ball.x");
    private final NumberField ballY = new NumberField("ball.y");
    private final NumberField ballVx = new NumberField("ball.vx");
    private final NumberField ballVy = new NumberField("ball.vy");
    private final JButton applyBall = new JButton("Apply");
    private final JPanel ballRows = new JPanel(new GridBagLayout());
    private final JTextField colour = new JTextField(6);
    private final JLabel swatch = new JLabel();
    private final JPanel colourRows = new JPanel(new GridBagLayout());
    private final DefaultListModel<Link> links = new DefaultListModel<>();
    private final JList<Link> linkList = new JList<>(links);
    private final JButton removeLink = new JButton("Remove");
    private String shownSelection;
    private List<String> shownGroup = List.of();

    private PropertiesPanel(Editor controller, Runnable focusBoard) {
        this.controller = controller;
        this.focusBoard = focusBoard;
        setLayout(new BorderLayout());
        setBorder(BorderFactory.createEmptyBorder(6, 6, 6, 6));
        // Stacked at the top at their natural heights, however tall the window is.
        JPanel stack = new JPanel();
        stack.setLayout(new BoxLayout(stack, BoxLayout.Y_AXIS));
        stack.add(section("Board", boardSection()));
        stack.add(Box.createVerticalStrut(8));
        stack.add(section("Selection", selectionSection()));
        add(stack, BorderLayout.NORTH);

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
        gravity.show(board.gravity());
        mu.show(board.mu());
        mu2.show(board.mu2());
        balls.setText(Integer.toString(board.gameRules().ballsPerGame()));
        extraBall.setText(board.gameRules().extraBallAt().isPresent()
                ? Long.toString(board.gameRules().extraBallAt().getAsLong()) : "");
        RefusedValue.unmark(extraBall);
        GameRules rules = board.gameRules();
        nudgeSpeed.setText(rules.nudge().map(n -> Decimals.format(n.speed())).orElse(""));
        tiltNudges.show(rules.tilt().nudges());
        tiltSeconds.show(rules.tilt().seconds());
        ballSave.show(rules.ballSaveSeconds());
        for (JTextField f : new JTextField[] {nudgeSpeed, tiltNudges, tiltSeconds, ballSave}) {
            RefusedValue.unmark(f);
        }

        shownSelection = controller.selected().orElse(null);
        shownGroup = controller.selection();
        // Of several selected, nothing one of them alone has is shown: an edit here would seem to apply to all.
        boolean several = shownGroup.size() > 1;
        Optional<Gizmo> gizmo = several ? Optional.empty() : controller.selectedGizmo();
        Optional<BallView> ball = several ? Optional.empty() : controller.selectedBall();
        selection.setText(several ? describe(shownGroup) : describe(gizmo, ball));
        // The ball's and the colour's rows keep their room when they do not apply, so that nothing below jumps.
        for (NumberField f : new NumberField[]{ballX, ballY, ballVx, ballVy}) {
            f.setEnabled(ball.isPresent());
            if (ball.isEmpty()) {
                f.setText("");
            }
        }
        Setting setting = gizmo.map(Gizmo::setting).orElse(new Setting.None());
        Optional<Setting.Launch> launch = as(setting, Setting.Launch.class);
        applyBall.setEnabled(ball.isPresent() || launch.isPresent());
        launch.ifPresent(l -> {
            ballVx.setEnabled(true);
            ballVy.setEnabled(true);
            ballVx.show(l.vx());
            ballVy.show(l.vy());
        });
        enableAll(nameRows, gizmo.isPresent() || ball.isPresent());
        name.setText(gizmo.map(Gizmo::name).or(() -> ball.map(BallView::name)).orElse(""));
        RefusedValue.unmark(name);
        cellX.setEnabled(gizmo.isPresent());
        cellY.setEnabled(gizmo.isPresent());
        cellX.setText(gizmo.map(g -> Integer.toString(g.x())).orElse(""));
        cellY.setText(gizmo.map(g -> Integer.toString(g.y())).orElse(""));
        RefusedValue.unmark(cellX);
        RefusedValue.unmark(cellY);
        enableAll(colourRows, gizmo.isPresent());
        colour.setText("");
        RefusedValue.unmark(colour);
        swatch.setBackground(colourRows.getBackground());
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
        Optional<Setting.Pull> absorber = as(setting, Setting.Pull.class);
        Optional<Plunger> pull = absorber.flatMap(Setting.Pull::plunger);
        plunger.setEnabled(absorber.isPresent());
        plunger.setSelected(pull.isPresent());
        for (NumberField f : new NumberField[] {plungerSpeed, plungerSeconds}) {
            f.setEnabled(pull.isPresent());
            f.setText("");
            RefusedValue.unmark(f);
        }
        pull.ifPresent(p -> {
            plungerSpeed.show(p.fullSpeed());
            plungerSeconds.show(p.pullSeconds());
        });
        gizmo.ifPresent(g -> {
            colour.setText(g.colour().map(PropertyEdits::hex).orElse(""));
            swatch.setBackground(BoardPainter.colourOf(g));
        });
        ball.ifPresent(b -> {
            ballX.show(b.position().x());
            ballY.show(b.position().y());
            ballVx.show(b.velocity().x());
            ballVy.show(b.velocity().y());
        });

        links.clear();
        if (shownSelection != null && !several) {
            String name = shownSelection;
            for (Connection c : board.connections()) {
                if (c.source().equals(TriggerSource.named(name)) || c.target().equals(name)) {
                    links.addElement(new Link(c.source() + " \u2192 " + c.target() + OrderWords.of(c.order()),
                            () -> controller.properties().disconnect(c.source(), c.target())));
                }
            }
            for (KeyBinding k : board.keyBindings()) {
                if (k.gizmo().equals(name)) {
                    links.addElement(new Link(KeyCodes.describe(k), () -> controller.properties().unbind(k)));
                }
            }
        }
        removeLink.setEnabled(!links.isEmpty());
    }

    /** The setting as its record, if it is one: each field of the panel shows the setting of one record. */
    private static <S extends Setting> Optional<S> as(Setting setting, Class<S> record) {
        return Optional.of(setting).filter(record::isInstance).map(record::cast);
    }

    private JComponent boardSection() {
        JPanel p = new JPanel(new GridBagLayout());
        row(p, 0, "Gravity (L/s\u00b2)", gravity);
        row(p, 1, "mu (per s)", mu);
        row(p, 2, "mu2 (per L)", mu2);
        row(p, 3, "Balls a game", balls);
        extraBall.setName("game.extra");
        extraBall.setToolTipText("The score that gives one extra ball; empty for none");
        row(p, 4, "Extra ball at", extraBall);
        nudgeSpeed.setName("game.nudge");
        nudgeSpeed.setToolTipText("L/s a nudge (arrow keys unless the file says) adds to every free ball; empty: none");
        row(p, 5, "Nudge (L/s)", nudgeSpeed);
        tiltNudges.setToolTipText("The nudge that tilts: that many within the seconds beside it");
        tiltSeconds.setToolTipText("The seconds within which that many nudges tilt");
        JPanel tilt = new JPanel(new BorderLayout(4, 0));
        tiltNudges.setColumns(2);
        tilt.add(tiltNudges, BorderLayout.WEST);
        tilt.add(new JLabel("in"), BorderLayout.CENTER);
        tiltSeconds.setColumns(3);
        JPanel seconds = new JPanel(new BorderLayout(4, 0));
        seconds.add(tiltSeconds, BorderLayout.CENTER);
        seconds.add(new JLabel("s"), BorderLayout.EAST);
        tilt.add(seconds, BorderLayout.EAST);
        row(p, 6, "Tilt: nudges", tilt);
        ballSave.setToolTipText("Seconds after a launch in which a drained ball is given back, once; 0: none");
        row(p, 7, "Ball save (s)", ballSave);
        JButton apply = new JButton("Apply");
        apply.setName("board.apply");
        apply.addActionListener(e -> applyBoard());
        for (JTextField f : new JTextField[]{gravity, mu, mu2, balls, extraBall, nudgeSpeed, tiltNudges, tiltSeconds,
                ballSave}) {
            f.addActionListener(e -> applyBoard());
            restoreOnEscape(f);
        }
        p.add(apply, constraints(1, 8));
        return p;
    }

    private JComponent selectionSection() {
        JPanel p = new JPanel(new GridBagLayout());
        selection.setName("selection");
        // Two lines' room whatever is selected: a longer description must not push the rows below it down.
        selection.setVerticalAlignment(SwingConstants.TOP);
        Dimension twoLines = new Dimension(SELECTION_WIDTH, 2 * selection.getFontMetrics(selection.getFont()).getHeight() + 4);
        selection.setPreferredSize(twoLines);
        selection.setMinimumSize(twoLines);
        GridBagConstraints c = constraints(0, 0);
        c.gridwidth = 2;
        p.add(selection, c);
        row(ballRows, 0, "Ball x", ballX);
        row(ballRows, 1, "Ball y", ballY);
        row(ballRows, 2, "vx (L/s)", ballVx);
        row(ballRows, 3, "vy (L/s)", ballVy);
        applyBall.setName("ball.apply");
        applyBall.addActionListener(e -> applyBall());
        for (NumberField f : new NumberField[]{ballX, ballY, ballVx, ballVy}) {
            f.addActionListener(e -> applyBall());
            restoreOnEscape(f);
        }
        ballRows.add(applyBall, constraints(1, 4));
        GridBagConstraints b = constraints(0, 1);
        b.gridwidth = 2;
        p.add(ballRows, b);

        p.add(colourRows(), wide(constraints(0, 2)));
        points.setToolTipText("What a real hit on the gizmo scores");
        points.addActionListener(e -> applyPoints());
        restoreOnEscape(points);
        JPanel pointsRow = new JPanel(new GridBagLayout());
        factor.setToolTipText("An accelerator: how many times faster a ball leaves it, 1 to 5");
        factor.setColumns(3);
        factor.addActionListener(e -> applyFactor());
        restoreOnEscape(factor);
        speed.setToolTipText("A spinner: turns a second, negative anticlockwise, up to 3 either way");
        speed.setColumns(3);
        speed.addActionListener(e -> applySpeed());
        restoreOnEscape(speed);
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
        restoreOnEscape(pair);
        p.add(absorberRows(), wide(constraints(0, 4)));
        p.add(nameRows(), wide(constraints(0, 5)));

        GridBagConstraints l = constraints(0, 6);
        l.gridwidth = 2;
        p.add(new JLabel("Connections and keys"), l);
        linkList.setName("links");
        linkList.setSelectionMode(ListSelectionModel.SINGLE_SELECTION);
        linkList.setVisibleRowCount(6);
        JScrollPane scroll = new JScrollPane(linkList);
        scroll.setPreferredSize(new Dimension(200, 150));
        // Never squeezed to a row: the panel scrolls instead (see gizmoball.app.BuildModeInstaller).
        scroll.setMinimumSize(scroll.getPreferredSize());
        GridBagConstraints s = constraints(0, 7);
        s.gridwidth = 2;
        s.fill = GridBagConstraints.BOTH;
        p.add(scroll, s);
        removeLink.setName("links.remove");
        removeLink.setToolTipText("Remove the chosen connection or key binding");
        removeLink.addActionListener(e -> {
            Link chosen = linkList.getSelectedValue();
            if (chosen != null) {
                chosen.remove().run();
            }
        });
        p.add(removeLink, constraints(1, 8));
        return p;
    }

    /**
     * An absorber's game: whether it is a drain, and whether it is a plunger with its full-pull speed and the seconds
     * of holding a full pull takes.
     */
    private JComponent absorberRows() {
        JPanel rows = new JPanel(new BorderLayout(0, 2));
        rows.add(drain, BorderLayout.NORTH);
        plunger.setName("gizmo.plunger");
        plunger.setToolTipText("Its key pulls it while held; the release launches faster the longer the hold");
        plunger.addActionListener(e -> applyPlunger());
        plungerSpeed.setToolTipText("A plunger: L/s of a full pull, above " + Decimals.format(Plunger.MIN_SPEED)
                + " and at most " + Decimals.format(Board.MAX_SPEED));
        plungerSeconds.setToolTipText("A plunger: seconds of holding for a full pull, "
                + Decimals.format(Plunger.MIN_PULL_SECONDS) + " to " + Decimals.format(Plunger.MAX_PULL_SECONDS));
        JPanel pull = new JPanel(new FlowLayout(FlowLayout.LEFT, 3, 0));
        pull.add(plunger);
        for (NumberField f : new NumberField[] {plungerSpeed, plungerSeconds}) {
            f.setColumns(3);
            f.addActionListener(e -> applyPlunger());
            restoreOnEscape(f);
            pull.add(f);
            pull.add(new JLabel(f == plungerSpeed ? "L/s" : "s"));
        }
        rows.add(pull, BorderLayout.SOUTH);
        return rows;
    }

    private void applyPlunger() {
        Optional<Gizmo> gizmo = controller.selectedGizmo();
        if (gizmo.isEmpty()) {
            return;
        }
        if (!plunger.isSelected()) {
            controller.properties().set(gizmo.get().name(), new Setting.Pull(Optional.empty()));
            focusBoard.run();
            return;
        }
        NumberField[] fields = {plungerSpeed, plungerSeconds};
        Optional<double[]> v = plungerSpeed.getText().isBlank() ? Optional.of(new double[] {
                Plunger.DEFAULT_FULL_SPEED, Plunger.DEFAULT_PULL_SECONDS}) : values(fields);
        if (v.isEmpty()) {
            return;
        }
        Map<JTextField, String> typed = new LinkedHashMap<>();
        for (NumberField f : fields) {
            typed.put(f, f.getText());
        }
        if (controller.properties().set(gizmo.get().name(), new Setting.Pull(Optional.of(new Plunger(v.get()[0], v.get()[1]))))) {
            focusBoard.run();
        } else {
            keepRefused(typed);
        }
    }

    /** The selected gizmo's own colour as #rrggbb (empty: its kind's), a swatch, a chooser and a reset. */
    private JComponent colourRows() {
        colour.setName("gizmo.colour");
        colour.setToolTipText("#rrggbb, or empty for the colour of the kind");
        colour.addActionListener(e -> applyColour(colour.getText()));
        swatch.setName("gizmo.colour.swatch");
        swatch.setOpaque(true);
        swatch.setPreferredSize(new Dimension(18, 18));
        swatch.setBorder(BorderFactory.createLineBorder(Color.DARK_GRAY));
        JPanel value = new JPanel(new BorderLayout(4, 0));
        value.add(swatch, BorderLayout.WEST);
        value.add(colour, BorderLayout.CENTER);
        row(colourRows, 0, "Colour", value);
        JButton choose = new JButton("Choose...");
        choose.setName("gizmo.colour.choose");
        choose.addActionListener(e -> {
            // Over the window, centred on it (over the panel it opened beside the window).
            Color chosen = JColorChooser.showDialog(SwingUtilities.getWindowAncestor(this),
                    "Colour of " + shownSelection, swatch.getBackground());
            if (chosen != null) {
                applyColour(PropertyEdits.hex(Rgb.of(chosen.getRGB())));
            }
        });
        JButton reset = new JButton("Kind's");
        reset.setName("gizmo.colour.reset");
        reset.setToolTipText("Back to the colour of the gizmo's kind");
        reset.addActionListener(e -> applyColour(""));
        // Under both columns: beside the label column they would not fit the panel's fixed width.
        JPanel buttons = new JPanel(new FlowLayout(FlowLayout.RIGHT, 4, 0));
        buttons.add(choose);
        buttons.add(reset);
        colourRows.add(buttons, wide(constraints(0, 1)));
        return colourRows;
    }

    /** The keyboard to the selection's name field, all of it selected, to rename or read on from there. */
    public void focusName() {
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
            restoreOnEscape(f);
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
                keepRefused(Map.of(name, typed));
            }
        }
    }

    private void applyCell() {
        Optional<Gizmo> gizmo = controller.selectedGizmo();
        Optional<double[]> v = values(cellX, cellY);
        if (gizmo.isEmpty() || v.isEmpty()) {
            return;
        }
        double x = v.get()[0];
        double y = v.get()[1];
        if (x != Math.rint(x) || y != Math.rint(y) || Math.abs(x) > Board.SIZE || Math.abs(y) > Board.SIZE) {
            refuse(x != Math.rint(x) || Math.abs(x) > Board.SIZE ? cellX : cellY,
                    "A cell is a whole number from 0 to " + (Board.SIZE - 1));
            return;
        }
        Map<JTextField, String> typed = new LinkedHashMap<>();
        typed.put(cellX, cellX.getText());
        typed.put(cellY, cellY.getText());
        if (controller.properties().moveGizmoTo(gizmo.get().name(), (int) x, (int) y)) {
            focusBoard.run();
        } else {
            keepRefused(typed);
        }
    }

    private void applyColour(String text) {
        controller.selectedGizmo().ifPresent(g -> {
            if (controller.properties().setColour(g.name(), text)) {
                focusBoard.run();
            } else {
                keepRefused(Map.of(colour, text));
            }
        });
    }

    /**
     * A refused apply leaves what was typed in the fields that asked for the change, each marked with the reason
     * (a rolled-back edit has shown the board's values again meanwhile).
     */
    private void keepRefused(Map<JTextField, String> typed) {
        String reason = controller.lastRefusal().orElse("refused");
        typed.forEach((field, text) -> {
            field.setText(text);
            RefusedValue.mark(field, reason);
        });
        typed.keySet().stream().findFirst().ifPresent(JTextField::requestFocusInWindow);
    }

    /** The typed texts of the fields whose numbers differ from the board's (the ones an apply changes). */
    private static Map<JTextField, String> changed(NumberField[] fields, double[] now) {
        Map<JTextField, String> typed = new LinkedHashMap<>();
        for (int i = 0; i < fields.length; i++) {
            if (fields[i].differsFrom(now[i])) {
                typed.put(fields[i], fields[i].getText());
            }
        }
        return typed;
    }

    private static GridBagConstraints wide(GridBagConstraints c) {
        c.gridwidth = 2;
        return c;
    }

    private void applyBoard() {
        NumberField[] constants = {gravity, mu, mu2};
        Optional<double[]> v = values(gravity, mu, mu2, balls);
        if (v.isEmpty()) {
            return;
        }
        OptionalLong extra = OptionalLong.empty();
        String extraText = extraBall.getText().strip();
        if (!extraText.isEmpty()) {
            OptionalDouble score = Decimals.parse(extraText);
            if (score.isEmpty() || score.getAsDouble() != Math.rint(score.getAsDouble())) {
                refuse(extraBall, "Extra ball at '" + extraText
                        + "': write a whole score, or nothing for no extra ball");
                return;
            }
            extra = OptionalLong.of((long) score.getAsDouble());
        }
        if (v.get()[3] != Math.rint(v.get()[3]) || Math.abs(v.get()[3]) > Integer.MAX_VALUE) {
            refuse(balls, "Balls a game: a whole number, 1 to " + GameRules.MAX_BALLS);
            return;
        }
        Board board = controller.board();
        Map<JTextField, String> typed = changed(constants, new double[] {board.gravity(), board.mu(), board.mu2()});
        if (!controller.properties().setConstants(v.get()[0], v.get()[1], v.get()[2])) {
            keepRefused(typed);
            return;
        }
        Map<JTextField, String> game = new LinkedHashMap<>();
        game.put(balls, balls.getText());
        game.put(extraBall, extraBall.getText());
        if (!controller.properties().setGame((int) v.get()[3], extra)) {
            keepRefused(game);
            return;
        }
        applyTable();
    }

    /** The nudge (empty: none), the tilt and the ball save, as one edit. */
    private void applyTable() {
        Optional<double[]> v = values(tiltNudges, tiltSeconds, ballSave);
        String speedText = nudgeSpeed.getText().strip();
        OptionalDouble speed = speedText.isEmpty() ? OptionalDouble.empty() : Decimals.parse(speedText);
        if (v.isEmpty() || !speedText.isEmpty() && speed.isEmpty()) {
            if (v.isPresent()) {
                refuse(nudgeSpeed, "Nudge '" + speedText + "' is not a number of L/s");
            }
            return;
        }
        Map<JTextField, String> typed = new LinkedHashMap<>();
        for (JTextField f : new JTextField[] {nudgeSpeed, tiltNudges, tiltSeconds, ballSave}) {
            typed.put(f, f.getText());
        }
        if (controller.properties().setTable(speed, v.get()[0], v.get()[1], v.get()[2])) {
            focusBoard.run();
        } else {
            keepRefused(typed);
        }
    }

    private void applyFactor() {
        Optional<Gizmo> gizmo = controller.selectedGizmo();
        Optional<double[]> v = values(factor);
        if (gizmo.isEmpty() || v.isEmpty()) {
            return;
        }
        String typed = factor.getText();
        if (controller.properties().set(gizmo.get().name(), new Setting.Factor(v.get()[0]))) {
            focusBoard.run();
        } else {
            keepRefused(Map.of(factor, typed));
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
            keepRefused(Map.of(pair, typed));
        }
    }

    private void applySpeed() {
        Optional<Gizmo> gizmo = controller.selectedGizmo();
        Optional<double[]> v = values(speed);
        if (gizmo.isEmpty() || v.isEmpty()) {
            return;
        }
        String typed = speed.getText();
        if (controller.properties().set(gizmo.get().name(), new Setting.Speed(v.get()[0]))) {
            focusBoard.run();
        } else {
            keepRefused(Map.of(speed, typed));
        }
    }

    private void applyPoints() {
        Optional<Gizmo> gizmo = controller.selectedGizmo();
        Optional<double[]> v = values(points);
        if (gizmo.isEmpty() || v.isEmpty()) {
            return;
        }
        double value = v.get()[0];
        if (value != Math.rint(value) || Math.abs(value) > Points.LIMIT) {
            refuse(points, "Points: a whole number from -" + Points.LIMIT + " to " + Points.LIMIT);
            return;
        }
        String typed = points.getText();
        if (controller.properties().setPoints(gizmo.get().name(), (int) value)) {
            focusBoard.run();
        } else {
            keepRefused(Map.of(points, typed));
        }
    }

    /** A value the panel itself refuses: said, kept in its field and marked, as every refused value is. */
    private void refuse(JTextField field, String reason) {
        controller.tell(reason);
        RefusedValue.mark(field, reason);
        field.requestFocusInWindow();
    }

    private void applyBall() {
        Optional<Gizmo> spawner = controller.selectedGizmo().filter(g -> g.setting() instanceof Setting.Launch);
        if (spawner.isPresent()) {
            applySpawnVelocity(spawner.get().name(), (Setting.Launch) spawner.get().setting());
            return;
        }
        Optional<BallView> ball = controller.selectedBall();
        NumberField[] fields = {ballX, ballY, ballVx, ballVy};
        Optional<double[]> v = values(fields);
        if (ball.isEmpty() || v.isEmpty()) {
            return;
        }
        BallView b = ball.get();
        Map<JTextField, String> typed = changed(fields,
                new double[] {b.position().x(), b.position().y(), b.velocity().x(), b.velocity().y()});
        if (controller.properties().setBall(b.name(), v.get()[0], v.get()[1], v.get()[2], v.get()[3])) {
            focusBoard.run();
        } else {
            keepRefused(typed);
        }
    }

    /** A spawner's balls' velocity, in the ball's vx and vy fields (its balls are what they describe). */
    private void applySpawnVelocity(String spawner, Setting.Launch now) {
        NumberField[] fields = {ballVx, ballVy};
        Optional<double[]> v = values(fields);
        if (v.isEmpty()) {
            return;
        }
        Map<JTextField, String> typed = changed(fields, new double[] {now.vx(), now.vy()});
        if (controller.properties().set(spawner, new Setting.Launch(v.get()[0], v.get()[1]))) {
            focusBoard.run();
        } else {
            keepRefused(typed);
        }
    }

    /** The numbers of a group of fields; empty, with every bad field marked and the first reported, if any is bad. */
    private Optional<double[]> values(NumberField... fields) {
        double[] values = new double[fields.length];
        NumberField firstBad = null;
        for (int i = 0; i < fields.length; i++) {
            OptionalDouble v = fields[i].value();
            if (v.isPresent()) {
                values[i] = v.getAsDouble();
            } else if (firstBad == null) {
                firstBad = fields[i];
            }
        }
        if (firstBad != null) {
            controller.tell(firstBad.getToolTipText());
            firstBad.requestFocusInWindow();
            return Optional.empty();
        }
        return Optional.of(values);
    }

    /** Esc in a field puts the board's values back (dropping marks) and returns the keyboard to the board. */
    private void restoreOnEscape(JTextField field) {
        field.getInputMap(JComponent.WHEN_FOCUSED).put(KeyStroke.getKeyStroke(KeyEvent.VK_ESCAPE, 0), "restore");
        field.getActionMap().put("restore", new AbstractAction() {
            @Override
            public void actionPerformed(ActionEvent e) {
                refresh();
                focusBoard.run();
            }
        });
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

    private static void enableAll(Container rows, boolean enabled) {
        for (Component c : rows.getComponents()) {
            c.setEnabled(enabled);
            if (c instanceof Container inner) {
                enableAll(inner, enabled);
            }
        }
    }

    /** "<b>name</b>: what", wrapped within the label's width. */
    private static String named(String name, String what) {
        return "<html><body style='width: " + (SELECTION_WIDTH - 10) + "px'><b>" + name + "</b>: " + what
                + "</body></html>";
    }


    private static JComponent section(String title, JComponent content) {
        content.setBorder(BorderFactory.createTitledBorder(title));
        content.setAlignmentX(LEFT_ALIGNMENT);
        return content;
    }

    private static void row(JPanel p, int y, String label, JComponent field) {
        p.add(new JLabel(label), constraints(0, y));
        p.add(field, constraints(1, y));
    }

    private static GridBagConstraints constraints(int x, int y) {
        GridBagConstraints c = new GridBagConstraints();
        c.gridx = x;
        c.gridy = y;
        c.anchor = GridBagConstraints.WEST;
        c.insets = new Insets(2, 2, 2, 2);
        c.fill = GridBagConstraints.HORIZONTAL;
        c.weightx = x;
        return c;
    }
}
