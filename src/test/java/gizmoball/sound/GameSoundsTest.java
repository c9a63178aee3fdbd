package gizmoball.sound;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.within;

import gizmoball.model.Board;
import gizmoball.model.KeyEdge;
import gizmoball.model.gizmo.GizmoKind;
import gizmoball.model.loop.PlayEvent;
import java.util.ArrayList;
import java.util.List;
import java.util.Optional;
import org.junit.jupiter.api.Test;

/** The model's play events of real ticks, and the cues they become. */
class GameSoundsTest {
    private final Board board = new Board();
    private final List<PlayEvent> events = new ArrayList<>();

    GameSoundsTest() {
        board.setFriction(0, 0);
        board.addObserver((b, change) -> events.addAll(b.lastTick().events()));
    }

    private void ticks(int n) {
        for (int i = 0; i < n; i++) {
            board.tick(Board.DEFAULT_TICK);
        }
    }

    @Test
    void aBallFallingOntoABumperClicksAtItsPitchAsLoudAsItsImpact() {
        board.addGizmo(GizmoKind.CIRCLE, "C", 10, 10);
        board.addBall("B", 10.5, 2, 0, 0);
        ticks(60);
        PlayEvent.Hit hit = events.stream().filter(e -> e instanceof PlayEvent.Hit).map(PlayEvent.Hit.class::cast)
                .findFirst().orElseThrow();
        // Dropped from rest 7.75 L above the contact (centre at y = 9.75): v = sqrt(2 g h) = 19.7 L/s.
        assertThat(hit.kind()).isEqualTo(GizmoKind.CIRCLE);
        assertThat(hit.speed()).isCloseTo(Math.sqrt(2 * 25 * 7.75), within(0.5));
        Cue cue = Sounds.cueFor(hit).orElseThrow();
        assertThat(cue.kind()).isEqualTo(Cue.Kind.CLICK);
        assertThat(cue.pitchHz()).isEqualTo(Sounds.pitchOf(GizmoKind.CIRCLE));
        assertThat(cue.gain()).isCloseTo(hit.speed() / Sounds.FULL_SPEED, within(1e-12));
    }

    @Test
    void captureFireAndFlipperEachHaveTheirSound() {
        board.addAbsorber("A", 0, 19, 20, 20);
        board.addGizmo(GizmoKind.LEFT_FLIPPER, "LF", 2, 2);
        board.bindKey(90, KeyEdge.DOWN, "LF");
        board.addBall("B", 10.5, 17, 0, 0);
        ticks(40);
        board.trigger("A");
        board.keyDown(90);
        ticks(1);
        List<Optional<Cue.Kind>> kinds = events.stream().map(e -> Sounds.cueFor(e).map(Cue::kind)).toList();
        assertThat(kinds).contains(Optional.of(Cue.Kind.THUNK), Optional.of(Cue.Kind.LAUNCH),
                Optional.of(Cue.Kind.SWISH));
        assertThat(events).anyMatch(e -> e instanceof PlayEvent.Captured c && c.absorber().equals("A"))
                .anyMatch(e -> e instanceof PlayEvent.Fired f && f.absorber().equals("A"))
                .anyMatch(e -> e instanceof PlayEvent.Swing s && s.flipper().equals("LF") && s.up());
    }

    @Test
    void wallsAndBallsClickLowAndHigh() {
        board.setGravity(0);
        board.addBall("B", 1, 10, -20, 0);
        board.addBall("C", 5, 5, 20, 0);
        board.addBall("D", 9, 5, -20, 0);
        ticks(10);
        List<Cue> clicks = events.stream().map(Sounds::cueFor).flatMap(Optional::stream).toList();
        assertThat(clicks).extracting(Cue::pitchHz).contains(220.0, 1320.0);
    }
}
