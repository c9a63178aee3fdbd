package gizmoball.model.loop;

import java.util.SplittableRandom;

import physics.Vect;

/**
 * Vectors for holding a reckoning on the components to the API's bits: mostly board-sized components, some zero, tiny
 * (down to subnormal squares), huge (overflowing squares), infinite or NaN, as a {@code Vect} holds them.
 */
final class OddVects {
    private OddVects() {
    }

    static Vect vect(SplittableRandom random) {
        return new Vect(component(random), component(random));
    }

    private static double component(SplittableRandom random) {
        return switch (random.nextInt(20)) {
            case 0 -> 0;
            case 1 -> random.nextDouble(-1, 1) * Double.MIN_NORMAL * 64;
            case 2 -> random.nextDouble(-1, 1) * 1e300;
            case 3 -> random.nextBoolean() ? Double.POSITIVE_INFINITY : Double.NaN;
            default -> random.nextDouble(-25, 25);
        };
    }
}
