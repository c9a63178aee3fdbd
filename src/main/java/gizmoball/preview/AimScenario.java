package gizmoball.preview;

import gizmoball.editor.Preview;
import gizmoball.editor.Tool;
import gizmoball.model.Board;
import gizmoball.model.BoardEditException;
import gizmoball.model.gizmo.GizmoKind;
import java.util.Optional;

/**
 * The board the aim preview plays: the design as it would be if the gesture in progress were finished now
 * (a ball being placed or moved, a gizmo being placed or moved, a group being moved, a rectangle being filled), and
 * the ball whose path is drawn. The design
 * itself is never changed; a gesture that would be refused changes nothing.
 */
public record AimScenario(Board board, String ball) {

    /**
     * What the editor shows now, as a board to predict on; empty when no ball is placed, moved or followed.
     * {@code followed} is the ball to predict when the selection is not a ball (a gizmo being placed or moved).
     */
    public static Optional<AimScenario> of(Board design, Tool tool, Optional<Preview> preview,
                                           Optional<String> selected, Optional<String> followed) {
        Board board = design.copy();
        Optional<String> selectedBall = selected.filter(name -> design.ball(name).isPresent())
                .or(() -> followed.filter(name -> design.ball(name).isPresent()));
        Optional<String> selectedGizmo = selected.filter(name -> design.gizmo(name).isPresent());
        String ball = selectedBall.orElse(null);
        try {
            if (preview.isPresent() && preview.get().fits()) {
                Preview p = preview.get();
                if (p instanceof Preview.BallPlacement placing) {
                    if (tool == Tool.BALL) {
                        ball = unusedName(board);
                        board.addBall(ball, placing.x(), placing.y(), placing.vx(), placing.vy());
                    } else if (ball != null) {
                        board.moveBall(ball, placing.x(), placing.y());
                    }
                } else if (p instanceof Preview.Footprint f) {
                    Optional<GizmoKind> kind = tool.kind();
                    if (kind.filter(GizmoKind::sizedByCorners).isPresent()) {
                        board.addAbsorber(unusedName(board), f.x(), f.y(), f.x() + f.width(), f.y() + f.height());
                    } else if (kind.isPresent()) {
                        board.addGizmo(kind.get(), unusedName(board), f.x(), f.y());
                    } else if (selectedGizmo.isPresent()) {
                        board.moveGizmo(selectedGizmo.get(), f.x(), f.y());
                    }
                } else if (p instanceof Preview.Group group) {
                    if (!group.moving().isEmpty()) {
                        board.moveGroup(group.moving(), group.dx(), group.dy());
                    } else if (tool.kind().isPresent()) {
                        for (Preview part : group.parts()) {
                            Preview.Footprint f = (Preview.Footprint) part;
                            board.addGizmo(tool.kind().get(), unusedName(board), f.x(), f.y());
                        }
                    }
                }
            }
        } catch (BoardEditException e) {
            // The editor's dry run said it fits; should the board disagree, predict on the board as it is.
            board = design.copy();
            ball = selectedBall.orElse(null);
        }
        return ball == null ? Optional.empty() : Optional.of(new AimScenario(board, ball));
    }

    private static String unusedName(Board board) {
        for (int i = 0; ; i++) {
            String name = "aim-preview-" + i;
            if (board.gizmo(name).isEmpty() && board.ball(name).isEmpty()) {
                return name;
            }
        }
    }
}
