package physics;

import java.util.Random;
import java.util.stream.LongStream;

/** Reproducible random inputs for the property tests: each case is built from its own printed seed. */
final class RandomScene {
    /** Base of the case seeds; case i uses BASE_SEED + i. */
    static final long BASE_SEED = 20261130L;

    final long seed;
    private final Random random;

    RandomScene(long seed) {
        this.seed = seed;
        this.random = new Random(seed);
    }

    /** Seeds for {@code count} cases, for {@code @MethodSource}. */
    static LongStream seeds(int count) {
        return LongStream.range(BASE_SEED, BASE_SEED + count);
    }

    double between(double low, double high) {
        return low + (high - low) * random.nextDouble();
    }

    /** A point in the square [-size, size]^2. */
    Vect point(double size) {
        return new Vect(between(-size, size), between(-size, size));
    }

    /** A vector of length in [minLength, maxLength] in a uniformly random direction. */
    Vect vector(double minLength, double maxLength) {
        return new Vect(new Angle(between(0, 2 * Math.PI)), between(minLength, maxLength));
    }

    boolean coin() {
        return random.nextBoolean();
    }

    @Override
    public String toString() {
        return "seed " + seed;
    }
}
