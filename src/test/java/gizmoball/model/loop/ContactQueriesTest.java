package gizmoball.model.loop;

import static org.assertj.core.api.Assertions.assertThat;

import gizmoball.model.Board;
import gizmoball.model.LoopViews;

import java.util.ArrayList;
import java.util.List;

import org.junit.jupiter.api.Test;

import physics.Vect;

/**
 * The queries of {@link Contacts} read and change nothing (docs/design.md, "The tick"): only the refresh of stage 1,
 * which keeps or finds contacts, puts a ball found slightly inside its surface back to touching.
 */
class ContactQueriesTest {
    private static final double R = Board.BALL_RADIUS;
    /** Inside the floor by more than the snap depth (a tenth of the contact tolerance), within the contact tolerance. */
    private static final double DEPTH = Tolerances.CONTACT / 2;

    private static Ball ballSunkIntoTheFloor(Board board) {
        board.setFriction(0, 0);
        board.addBall("B", 10, Board.SIZE - R, 0, 0);
        Ball ball = LoopViews.of(board).ball("B");
        ball.moveTo(new Vect(10, Board.SIZE - R + DEPTH));   // as rounding of play may leave it
        Contacts.attach(ball, new ContactRef.Wall(2));
        return ball;
    }

    @Test
    void askingForTheNormalsMovesNoBall() {
        Board board = new Board();
        Ball ball = ballSunkIntoTheFloor(board);
        LoopView view = LoopViews.of(board);
        Contacts contacts = new Contacts(view, view.gravity(), 1.0 / 60);
        Vect before = ball.position();

        List<Vect> normals = contacts.normals(ball);
        Vect normal = contacts.normal(ball, new ContactRef.Wall(2));
        List<Vect> besides = contacts.normalsBesides(ball, new ContactRef.Wall(0), new ArrayList<>());

        assertThat(normals).containsExactly(new Vect(0, -1));
        assertThat(normal).isEqualTo(new Vect(0, -1));
        assertThat(besides).containsExactly(new Vect(0, -1));
        assertThat(ball.position()).isEqualTo(before);
        assertThat(ball.velocity()).isEqualTo(Vect.ZERO);
    }

    @Test
    void theRefreshPutsTheBallBackToTouching() {
        Board board = new Board();
        Ball ball = ballSunkIntoTheFloor(board);
        LoopView view = LoopViews.of(board);
        Contacts contacts = new Contacts(view, view.gravity(), 1.0 / 60);

        assertThat(contacts.refresh(ball)).containsExactly(new Vect(0, -1));
        assertThat(ball.position()).isEqualTo(new Vect(10, Board.SIZE - R));
    }
}
