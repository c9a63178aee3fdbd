package gizmoball.view;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.within;

import java.awt.geom.Point2D;
import java.util.Random;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;
import org.junit.jupiter.params.provider.ValueSource;
import physics.Vect;

class BoardTransformTest {
    @ParameterizedTest(name = "{0}x{1} margin {2}: {3} px per L at ({4}, {5})")
    @CsvSource({
        // width, height, margin, scale = floor((min - 2 margin) / 20), board's top-left pixel (centred)
        "400, 400, 0, 20, 0, 0",
        "612, 612, 6, 30, 6, 6",
        "800, 600, 0, 30, 100, 0",
        "600, 811, 0, 30, 0, 105",
        "419, 419, 0, 20, 9, 9",
        "10, 10, 0, 1, -5, -5",
    })
    void largestWholePixelScaleCentred(int width, int height, int margin, double scale, double left, double top) {
        BoardTransform t = BoardTransform.fit(width, height, margin);

        assertThat(t.scale()).isEqualTo(scale);
        assertThat(t.toScreen(0, 0)).isEqualTo(new Point2D.Double(left, top));
        assertThat(t.toScreen(20, 20)).isEqualTo(new Point2D.Double(left + 20 * scale, top + 20 * scale));
    }

    @ParameterizedTest
    @ValueSource(longs = {1, 2, 3})
    void toBoardUndoesToScreenAndAgreesWithTheAffineTransform(long seed) {
        Random random = new Random(seed);
        BoardTransform t = BoardTransform.fit(100 + random.nextInt(900), 100 + random.nextInt(900), random.nextInt(10));
        for (int i = 0; i < 100; i++) {
            double x = random.nextDouble() * 20;
            double y = random.nextDouble() * 20;
            Point2D screen = t.toScreen(x, y);
            Vect back = t.toBoard(screen.getX(), screen.getY());
            Point2D affine = t.boardToScreen().transform(new Point2D.Double(x, y), null);

            assertThat(back.x()).as("seed %d case %d", seed, i).isCloseTo(x, within(1e-9));
            assertThat(back.y()).as("seed %d case %d", seed, i).isCloseTo(y, within(1e-9));
            assertThat(affine.getX()).as("seed %d case %d", seed, i).isCloseTo(screen.getX(), within(1e-9));
            assertThat(affine.getY()).as("seed %d case %d", seed, i).isCloseTo(screen.getY(), within(1e-9));
        }
    }
}
