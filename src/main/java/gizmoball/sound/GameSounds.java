package gizmoball.sound;

import gizmoball.model.Board;
import gizmoball.model.BoardChange;
import gizmoball.model.loop.PlayEvent;

/**
 * Makes a board audible: after each tick, the events of the model's tick report (hits with their impact
 * speed, captures, fires, flipper swings) become cues for the player. Playing only queues them, so the
 * tick's observers are not held up by audio.
 */
public final class GameSounds {
    private GameSounds() {
    }

    public static void attach(Board board, SoundPlayer player) {
        board.addObserver((Board b, BoardChange change) -> {
            if (change == BoardChange.TICK && player.isEnabled()) {
                for (PlayEvent event : b.lastTick().events()) {
                    Sounds.cueFor(event).ifPresent(player::play);
                }
            }
        });
    }
}
