package gizmoball.replay;

import static org.assertj.core.api.Assertions.assertThat;

import gizmoball.boardfile.BoardContents;
import gizmoball.boardfile.BoardFiles;
import gizmoball.model.Board;
import gizmoball.model.game.KeyPress;
import gizmoball.model.game.Notice;
import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;

/**
 * A two-player game with a plunger, nudges, a tilt and a ball save, written to a replay file and read back, plays
 * from the board as built to the same scores, notices, drains and balls, bit for bit.
 */
class SkillReplayTest {
    static final String TABLE = """
            Circle C1 8 6
            Circle C2 12 9
            Triangle T 3 3
            Square S 15 4
            LeftFlipper LF 6 17
            RightFlipper RF 12 17
            Absorber P 19 19 20 20
            Absorber D 0 19 19 20
            Ball B 19.75 19.75 0.0 0.0
            KeyConnect key 90 down LF
            KeyConnect key 90 up LF
            KeyConnect key 47 down RF
            KeyConnect key 47 up RF
            KeyConnect key 32 down P
            Gravity 25.0
            Friction 0.025 0.025
            #@Plunger P 60.0 1.0
            #@Balls 2
            #@Nudge 4.0 37 39 38
            #@Tilt 3 2.0
            #@BallSave 3.0
            #@Drain D
            """;
    private static final double DT = Board.DEFAULT_TICK;

    /** Pulls for a while, launches, flips and nudges every ball; nudges thrice fast on the third to tilt. */
    static KeyScript script() {
        List<KeyPress> keys = new ArrayList<>();
        for (int ball = 0; ball < 8; ball++) {
            long start = 20 + ball * 900L;
            keys.add(new KeyPress(start, KeyPress.Motion.DOWN, 32));
            keys.add(new KeyPress(start + 20 + 7 * ball, KeyPress.Motion.UP, 32));
            for (int flip = 0; flip < 12; flip++) {
                long at = start + 120 + flip * 60L;
                int key = flip % 2 == 0 ? 90 : 47;
                keys.add(new KeyPress(at, KeyPress.Motion.DOWN, key));
                keys.add(new KeyPress(at + 8, KeyPress.Motion.UP, key));
                if (flip % 4 == 1 || ball == 2 && flip < 3) {
                    keys.add(new KeyPress(at + 9, KeyPress.Motion.DOWN, 37 + flip % 3));
                    keys.add(new KeyPress(at + 10, KeyPress.Motion.UP, 37 + flip % 3));
                }
            }
        }
        return new KeyScript(keys);
    }

    @Test
    void aTwoPlayerGameWithEveryFeatureReplaysBitForBit() throws Exception {
        Board board = BoardFiles.load("table", TABLE);
        board.setPlayers(2);
        long ticks = 8 * 900L;
        ScriptedPlay.play(board, script(), ticks, DT);
        assertThat(board.game().notices()).extracting(Notice::kind).contains(Notice.Kind.TILT);
        assertReplaysBitForBit(TABLE, board);
    }

    /**
     * No gravity: the plunger that is the drain fires the ball up into the square and it comes straight back; the
     * each ball is saved once, and its next drain hands the ball to the other player: eight launches for two balls
     * each.
     */
    @Test
    void turnsAndBallSavesReplayBitForBit() throws Exception {
        String oneShot = """
                Square S 19 2
                Absorber A 0 19 20 20
                Ball B 19.75 19.75 0.0 0.0
                KeyConnect key 32 down A
                Gravity 0.0
                Friction 0.0 0.0
                #@Plunger A 60.0 1.0
                #@Balls 2
                #@Nudge 4.0 37 39 38
                #@BallSave 3.0
                #@Drain A
                """;
        Board board = BoardFiles.load("one-shot", oneShot);
        board.setPlayers(2);
        List<KeyPress> keys = new ArrayList<>();
        for (int launch = 0; launch < 8; launch++) {
            long start = 10 + launch * 200L;
            keys.add(new KeyPress(start, KeyPress.Motion.DOWN, 32));
            keys.add(new KeyPress(start + 30 + 5 * launch, KeyPress.Motion.UP, 32));
            keys.add(new KeyPress(start + 31 + 5 * launch, KeyPress.Motion.DOWN, 38));
            keys.add(new KeyPress(start + 32 + 5 * launch, KeyPress.Motion.UP, 38));
        }
        ScriptedPlay.play(board, new KeyScript(keys), 1700, DT);
        Notice.Kind saved = Notice.Kind.BALL_SAVED;
        Notice.Kind next = Notice.Kind.NEXT_PLAYER;
        assertThat(board.game().notices()).extracting(Notice::kind)
                .containsExactly(saved, next, saved, next, saved, next, saved);
        assertThat(board.game().isOver()).isTrue();
        assertReplaysBitForBit(oneShot, board);
    }

    private static void assertReplaysBitForBit(String asBuilt, Board board) throws Exception {

        Replay replay = ReplayFiles.fromJson("replay", ReplayFiles.toJson(Replay.of(asBuilt, board, DT)));
        assertThat(replay.players()).isEqualTo(2);
        Board again = replay.replayed("table");

        assertThat(again.game().players()).isEqualTo(2);
        assertThat(again.game().score(0)).isEqualTo(board.game().score(0));
        assertThat(again.game().score(1)).isEqualTo(board.game().score(1));
        assertThat(again.game().notices()).isEqualTo(board.game().notices());
        assertThat(again.game().scoringHits()).isEqualTo(board.game().scoringHits());
        assertThat(again.game().drains()).isEqualTo(board.game().drains());
        assertThat(again.game().isOver()).isEqualTo(board.game().isOver());
        assertThat(BoardContents.of(again).balls()).isEqualTo(BoardContents.of(board).balls());
    }
}
