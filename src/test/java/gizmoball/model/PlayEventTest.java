package gizmoball.model;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.within;

import gizmoball.model.gizmo.GizmoKind;
import gizmoball.model.loop.PlayEvent;
import gizmoball.model.loop.TriggerSource;

import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;

/** Which ball a hit or a capture was and where its centre was then: what the aim preview marks on a path. */
class PlayEventTest {
    private final Board board = new Board();
    private final List<PlayEvent> events = new ArrayList<>();

    PlayEventTest() {
        board.setFriction(0, 0);
        board.addObserver((b, change) -> events.addAll(b.lastTick().events()));
    }

    @Test
    void aHitNamesTheBallAndWhereItsCentreWas() {
        board.addGizmo(GizmoKind.SQUARE, "S", 10, 10);
        board.addBall("B", 10.5, 2, 0, 0);
        board.addBall("Far", 2.5, 2, 0, 0);
        for (int i = 0; i < 60 && events.isEmpty(); i++) {
            board.tick(Board.DEFAULT_TICK);
        }
        PlayEvent.Hit hit = (PlayEvent.Hit) events.get(0);
        assertThat(hit.struck()).isEqualTo(TriggerSource.gizmo("S"));
        assertThat(hit.ball()).isEqualTo("B");
        // Falling straight down x = 10.5 onto the top face y = 10: the centre one radius above it.
        assertThat(hit.at().x()).isCloseTo(10.5, within(1e-9));
        assertThat(hit.at().y()).isCloseTo(10 - Board.BALL_RADIUS, within(1e-9));
    }

    @Test
    void aCaptureNamesTheBallAndWhereItTouchedTheAbsorber() {
        board.addAbsorber("A", 0, 19, 20, 20);
        board.addBall("B", 7.5, 17, 0, 0);
        for (int i = 0; i < 60 && events.isEmpty(); i++) {
            board.tick(Board.DEFAULT_TICK);
        }
        PlayEvent.Captured captured = (PlayEvent.Captured) events.get(0);
        assertThat(captured.absorber()).isEqualTo("A");
        assertThat(captured.ball()).isEqualTo("B");
        assertThat(captured.at().x()).isCloseTo(7.5, within(1e-9));
        assertThat(captured.at().y()).isCloseTo(19 - Board.BALL_RADIUS, within(1e-9));
    }

    /**
     * A ball let go 1e-4 L above a square meets it at sqrt(2 g h) = 0.071 L/s, far below the resting speed of two ticks
     * of gravity (2 g dt = 0.83 L/s): it comes to rest, which is no hit for the sound or the score.
     */
    @Test
    void aBallComingToRestOnASurfaceIsNoHit() {
        board.addGizmo(GizmoKind.SQUARE, "S", 10, 10);
        board.addBall("B", 10.5, 10 - Board.BALL_RADIUS - 1e-4, 0, 0);
        for (int i = 0; i < 120; i++) {
            board.tick(Board.DEFAULT_TICK);
        }
        assertThat(board.ball("B").orElseThrow().position().y()).isCloseTo(10 - Board.BALL_RADIUS, within(1e-9));
        assertThat(events).noneMatch(PlayEvent.Hit.class::isInstance);
    }

    /** A ball settling slowly onto another that lies on the floor rests on it: no hit either. */
    @Test
    void aBallSettlingOnAnotherIsNoHit() {
        board.addBall("Low", 10.5, Board.SIZE - Board.BALL_RADIUS, 0, 0);
        board.addBall("High", 10.5, Board.SIZE - 3 * Board.BALL_RADIUS - 1e-4, 0, 0);
        for (int i = 0; i < 120; i++) {
            board.tick(Board.DEFAULT_TICK);
        }
        assertThat(events).noneMatch(PlayEvent.Hit.class::isInstance);
    }
}
