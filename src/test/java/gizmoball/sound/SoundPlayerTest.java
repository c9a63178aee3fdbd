package gizmoball.sound;

import static org.assertj.core.api.Assertions.assertThat;

import gizmoball.model.gizmo.GizmoKind;
import java.util.List;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.TimeUnit;
import javax.sound.sampled.LineUnavailableException;
import org.junit.jupiter.api.Test;

/** The player's threading and failure handling; no test opens a real audio device. */
class SoundPlayerTest {
    private final List<String> notices = new CopyOnWriteArrayList<>();

    @Test
    void withoutAnAudioDeviceItSaysSoOnceAndStaysSilent() throws Exception {
        CountDownLatch tried = new CountDownLatch(1);
        SoundPlayer player = new SoundPlayer(notices::add, (format, bytes) -> {
            tried.countDown();
            throw new LineUnavailableException("no audio device");
        }, false);
        player.setEnabled(true);
        assertThat(tried.await(5, TimeUnit.SECONDS)).isTrue();
        awaitNotices(1);
        for (int i = 0; i < 100; i++) {
            player.play(Sounds.fire());
        }
        player.setEnabled(false);
        player.setEnabled(true);
        Thread.sleep(200);
        assertThat(notices).containsExactly("No audio device: sound off");
        player.close();
    }

    /** Issue 23, item 13: without a device sound is off, one answer for whoever asks. */
    @Test
    void withoutADeviceSoundIsOffWhateverIsAsked() throws Exception {
        SoundPlayer player = new SoundPlayer(notices::add, (format, bytes) -> {
            throw new LineUnavailableException("no audio device");
        }, false);
        assertThat(player.hasDevice()).isTrue();
        player.setEnabled(true);
        awaitNotices(1);

        assertThat(player.hasDevice()).isFalse();
        assertThat(player.isEnabled()).isFalse();
        player.setEnabled(true);
        assertThat(player.isEnabled()).isFalse();
        assertThat(notices).containsExactly(SoundPlayer.NO_DEVICE);
        player.close();
    }

    @Test
    void playingNeverWaitsForTheAudioThreadEvenWhenTheDeviceHangs() throws Exception {
        CountDownLatch release = new CountDownLatch(1);
        SoundPlayer player = new SoundPlayer(notices::add, (format, bytes) -> {
            try {
                release.await();
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
            }
            throw new LineUnavailableException("gave up");
        }, false);
        player.setEnabled(true);
        long start = System.nanoTime();
        for (int i = 0; i < 10_000; i++) {
            player.play(Sounds.gizmoHit(GizmoKind.CIRCLE, 20).orElseThrow());
        }
        // 10,000 hits into a bounded queue nobody drains: each returns at once (the excess is dropped).
        assertThat((System.nanoTime() - start) / 1e6).isLessThan(500);
        release.countDown();
        player.close();
    }

    @Test
    void aSilentPlayerNeverTriesTheDevice() throws Exception {
        SoundPlayer player = new SoundPlayer(notices::add, (format, bytes) -> {
            throw new AssertionError("opened a device");
        }, true);
        player.setEnabled(true);
        player.play(Sounds.capture());
        Thread.sleep(100);
        assertThat(notices).isEmpty();
    }

    @Test
    void theTestsRunWithSoundOff() {
        // build.gradle sets it for every test JVM: no test window ever plays a sound.
        assertThat(System.getProperty(SoundPlayer.DISABLE_PROPERTY)).isEqualTo("off");
    }

    private void awaitNotices(int n) throws InterruptedException {
        long deadline = System.currentTimeMillis() + 5000;
        while (notices.size() < n && System.currentTimeMillis() < deadline) {
            Thread.sleep(10);
        }
    }
}
