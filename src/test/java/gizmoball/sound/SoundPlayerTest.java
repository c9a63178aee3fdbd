package gizmoball.sound;

import static org.assertj.core.api.Assertions.assertThat;
import static org.junit.jupiter.api.Assertions.assertTimeoutPreemptively;

import gizmoball.model.gizmo.GizmoKind;
import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.Executor;
import javax.sound.sampled.LineUnavailableException;
import org.junit.jupiter.api.Test;

/**
 * The player's threading and failure handling. The audio loop runs on the test's own thread, when the test says
 * (through {@link HeldAudioLoop}), so every test sees exactly what the audio thread did; no test opens a real
 * audio device.
 */
class SoundPlayerTest {
    private final List<String> notices = new ArrayList<>();
    private final HeldAudioLoop audio = new HeldAudioLoop();
    private int opens;

    /** A machine without an audio device: every open fails, and is counted. */
    private SoundPlayer.LineFactory noDevice() {
        return (format, bytes) -> {
            opens++;
            throw new LineUnavailableException("no audio device");
        };
    }

    @Test
    void withoutAnAudioDeviceItSaysSoOnceAndStaysSilent() {
        SoundPlayer player = new SoundPlayer(notices::add, noDevice(), false, audio);
        player.setEnabled(true);
        audio.runAll();
        assertThat(opens).isEqualTo(1);
        assertThat(notices).containsExactly("No audio device: sound off");

        for (int i = 0; i < 100; i++) {
            player.play(Sounds.fire());
        }
        player.setEnabled(false);
        player.setEnabled(true);
        assertThat(audio.held()).as("audio loops started again").isZero();
        assertThat(opens).isEqualTo(1);
        assertThat(notices).containsExactly("No audio device: sound off");
        player.close();
    }

    /** Issue 23, item 13: without a device sound is off, one answer for whoever asks. */
    @Test
    void withoutADeviceSoundIsOffWhateverIsAsked() {
        SoundPlayer player = new SoundPlayer(notices::add, noDevice(), false, audio);
        assertThat(player.hasDevice()).isTrue();
        player.setEnabled(true);
        audio.runAll();

        assertThat(player.hasDevice()).isFalse();
        assertThat(player.isEnabled()).isFalse();
        player.setEnabled(true);
        assertThat(player.isEnabled()).isFalse();
        assertThat(notices).containsExactly(SoundPlayer.NO_DEVICE);
        player.close();
    }

    @Test
    void playingNeverWaitsForTheAudioThreadEvenWhenTheDeviceHangs() {
        SoundPlayer player = new SoundPlayer(notices::add, noDevice(), false, audio);
        player.setEnabled(true);
        // The audio loop is held, as behind a device that hangs: nobody drains the bounded queue. If a play
        // waited for room it would wait for ever; the bound only turns such a hang into a failure.
        assertTimeoutPreemptively(Duration.ofSeconds(30), () -> {
            for (int i = 0; i < 10_000; i++) {
                player.play(Sounds.gizmoHit(GizmoKind.CIRCLE, 20).orElseThrow());
            }
        });
        assertThat(audio.held()).isEqualTo(1);
        assertThat(opens).isZero();
        player.close();
    }

    @Test
    void aSilentPlayerNeverTriesTheDevice() {
        SoundPlayer player = new SoundPlayer(notices::add, noDevice(), true, audio);
        player.setEnabled(true);
        player.play(Sounds.capture());
        assertThat(audio.held()).as("audio loops started").isZero();
        audio.runAll();
        assertThat(opens).as("devices opened").isZero();
        assertThat(notices).isEmpty();
    }

    @Test
    void theTestsRunWithSoundOff() {
        // build.gradle sets it for every test JVM: no test window ever plays a sound.
        assertThat(System.getProperty(SoundPlayer.DISABLE_PROPERTY)).isEqualTo("off");
    }

    /** Holds the audio loop the player starts until the test runs it, on the test's thread. */
    private static final class HeldAudioLoop implements Executor {
        private final List<Runnable> held = new ArrayList<>();

        @Override
        public void execute(Runnable audioLoop) {
            held.add(audioLoop);
        }

        int held() {
            return held.size();
        }

        void runAll() {
            List<Runnable> now = List.copyOf(held);
            held.clear();
            now.forEach(Runnable::run);
        }
    }
}
