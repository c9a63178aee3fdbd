package gizmoball.controller;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;

class KeyRepeatFilterTest {
    private static final int WINDOW = 20;
    private static final int SPACE = 32;
    private static final int Z = 90;

    private final List<String> edges = new ArrayList<>();
    private final KeyRepeatFilter filter = new KeyRepeatFilter(new KeyRepeatFilter.Edges() {
        @Override
        public void down(int keyCode) {
            edges.add("down " + keyCode);
        }

        @Override
        public void up(int keyCode) {
            edges.add("up " + keyCode);
        }
    }, WINDOW);

    @Test
    void aPressAndALaterReleaseGiveOneDownAndOneUp() {
        filter.pressed(SPACE);
        filter.released(SPACE, 1000);
        filter.flush(1000 + WINDOW);

        assertThat(edges).containsExactly("down 32", "up 32");
    }

    @Test
    void repeatedPressesWithoutReleaseAreOneDown() {
        for (int i = 0; i < 10; i++) {
            filter.pressed(SPACE);
        }

        assertThat(edges).containsExactly("down 32");
    }

    @Test
    void x11ReleasePressPairsOfAHeldKeyAreDropped() {
        filter.pressed(SPACE);
        for (int t = 500; t < 1500; t += 33) {
            filter.released(SPACE, t);
            filter.pressed(SPACE);
            filter.flush(t + WINDOW);
        }
        filter.released(SPACE, 2000);
        filter.flush(2000 + WINDOW);

        assertThat(edges).containsExactly("down 32", "up 32");
    }

    @Test
    void aReleaseIsHeldBackOnlyForThePairWindow() {
        filter.pressed(SPACE);
        filter.released(SPACE, 1000);
        filter.flush(1000 + WINDOW - 1);
        assertThat(edges).containsExactly("down 32");

        filter.flush(1000 + WINDOW);
        assertThat(edges).containsExactly("down 32", "up 32");
        assertThat(filter.hasPendingReleases()).isFalse();
    }

    @Test
    void aNewPressAfterADeliveredReleaseIsANewDown() {
        filter.pressed(SPACE);
        filter.released(SPACE, 1000);
        filter.flush(1000 + WINDOW);
        filter.pressed(SPACE);

        assertThat(edges).containsExactly("down 32", "up 32", "down 32");
    }

    @Test
    void keysAreFilteredIndependently() {
        filter.pressed(SPACE);
        filter.pressed(Z);
        filter.released(Z, 1000);
        filter.pressed(SPACE);
        filter.flush(1000 + WINDOW);

        assertThat(edges).containsExactly("down 32", "down 90", "up 90");
    }

    @Test
    void aReleaseWithoutAPressIsIgnored() {
        filter.released(SPACE, 1000);
        filter.flush(1000 + WINDOW);

        assertThat(edges).isEmpty();
        assertThat(filter.hasPendingReleases()).isFalse();
    }

    @Test
    void releaseAllReleasesHeldAndPendingKeysOnce() {
        filter.pressed(SPACE);
        filter.pressed(Z);
        filter.released(Z, 1000);
        filter.releaseAll();
        filter.flush(1000 + WINDOW);

        assertThat(edges).hasSize(4).contains("up 32", "up 90");
        assertThat(edges.subList(0, 2)).containsExactly("down 32", "down 90");
    }
}
