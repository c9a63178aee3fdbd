package gizmoball.sound;

import java.awt.GraphicsEnvironment;
import java.util.concurrent.ArrayBlockingQueue;
import java.util.concurrent.BlockingQueue;
import java.util.concurrent.Executor;
import java.util.concurrent.TimeUnit;
import java.util.function.Consumer;
import javax.sound.sampled.AudioFormat;
import javax.sound.sampled.AudioSystem;
import javax.sound.sampled.LineUnavailableException;
import javax.sound.sampled.SourceDataLine;

/**
 * Plays cues on a dedicated daemon thread, started the first time sound is turned on. {@link #play} only offers the cue to a bounded queue and
 * returns: the event thread and the game loop never wait for audio, and when the queue is full (the audio
 * thread is behind) the cue is dropped. The audio thread synthesizes, mixes and writes to the device in
 * blocks of a few milliseconds.
 * <p>
 * Without an audio device the player goes silent and says so once through its notice callback. It never
 * opens a device in a headless JVM, nor when the system property {@value #DISABLE_PROPERTY} is
 * {@code off} (the tests set it).
 */
public final class SoundPlayer implements AutoCloseable {
    public static final String DISABLE_PROPERTY = "gizmoball.sound";
    /** What the player is told, once, and again when asking for sound without a device. */
    public static final String NO_DEVICE = "No audio device: sound off";
    private static final int QUEUE_CAPACITY = 64;
    private static final int BLOCK_FRAMES = 256;
    /** The device's buffer: about 46 ms, enough to ride out a scheduling hiccup, short enough to feel immediate. */
    private static final int LINE_BUFFER_FRAMES = 2048;
    private static final AudioFormat FORMAT = new AudioFormat(Synth.SAMPLE_RATE, 16, 1, true, false);

    /** Where the samples go: the system's default audio line, opened in {@link #FORMAT}. */
    @FunctionalInterface
    interface LineFactory {
        SourceDataLine open(AudioFormat format, int bufferBytes) throws LineUnavailableException;
    }

    private final BlockingQueue<Cue> queue = new ArrayBlockingQueue<>(QUEUE_CAPACITY);
    private final Consumer<String> notice;
    private final LineFactory lines;
    /** Runs the audio loop, once: a daemon thread of its own in the game, the test's own hand in tests. */
    private final Executor audio;
    private boolean started;
    /** The thread running the audio loop, once it runs: {@link #close} interrupts it. */
    private volatile Thread audioThread;
    private volatile boolean enabled;
    private volatile boolean silent;
    /** Set once the device could not be opened or failed: from then on sound is off, whatever is asked. */
    private volatile boolean noDevice;

    /** {@code notice} is told once, from the audio thread, if the sound cannot be played. */
    public SoundPlayer(Consumer<String> notice) {
        this(notice, SoundPlayer::systemLine,
                GraphicsEnvironment.isHeadless() || "off".equals(System.getProperty(DISABLE_PROPERTY)),
                SoundPlayer::daemonThread);
    }

    /**
     * With another line (the tests: a machine whose audio fails) and another runner of the audio loop;
     * {@code silent}: never open a line.
     */
    SoundPlayer(Consumer<String> notice, LineFactory lines, boolean silent, Executor audio) {
        this.notice = notice;
        this.lines = lines;
        this.silent = silent;
        this.audio = audio;
    }

    private static void daemonThread(Runnable audioLoop) {
        Thread thread = new Thread(audioLoop, "gizmoball-audio");
        thread.setDaemon(true);
        thread.start();
    }

    /** Sound on or off; the audio thread starts, and opens the device, the first time sound is turned on. */
    public void setEnabled(boolean on) {
        enabled = on;
        if (on && !silent && !started) {
            started = true;
            audio.execute(this::run);
        }
        if (!on) {
            queue.clear();
        }
    }

    /** Whether sound is on: asked for, and not without a device (one answer for the menu and the messages). */
    public boolean isEnabled() {
        return enabled && !noDevice;
    }

    /** False once the audio device was found missing or failed; the game then stays silent. */
    public boolean hasDevice() {
        return !noDevice;
    }

    /** Never blocks. Ignored while off, silent, or when the audio thread is too far behind. */
    public void play(Cue cue) {
        if (enabled && !silent) {
            queue.offer(cue);
        }
    }

    @Override
    public void close() {
        silent = true;
        Thread running = audioThread;
        if (running != null) {
            running.interrupt();
        }
    }

    private static SourceDataLine systemLine(AudioFormat format, int bufferBytes) throws LineUnavailableException {
        SourceDataLine line = AudioSystem.getSourceDataLine(format);
        line.open(format, bufferBytes);
        return line;
    }

    private void run() {
        audioThread = Thread.currentThread();
        if (silent) {
            return;
        }
        try (SourceDataLine line = lines.open(FORMAT, LINE_BUFFER_FRAMES * FORMAT.getFrameSize())) {
            line.start();
            mix(line);
        } catch (LineUnavailableException | RuntimeException e) {
            // No device, none in this format, no permission, or one that failed while playing: all mean silence.
            silent = true;
            noDevice = true;
            queue.clear();
            notice.accept(NO_DEVICE);
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
    }

    private void mix(SourceDataLine line) throws InterruptedException {
        Mixer mixer = new Mixer();
        float[] block = new float[BLOCK_FRAMES];
        byte[] pcm = new byte[BLOCK_FRAMES * 2];
        while (!silent) {
            Cue cue = mixer.isIdle() ? queue.poll(1, TimeUnit.SECONDS) : queue.poll();
            while (cue != null) {
                mixer.add(Synth.render(cue));
                cue = queue.poll();
            }
            if (!mixer.isIdle()) {
                mixer.render(block);
                Mixer.toPcm16(block, pcm);
                line.write(pcm, 0, pcm.length);
            }
        }
    }
}
