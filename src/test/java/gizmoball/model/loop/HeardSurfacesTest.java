package gizmoball.model.loop;

import static org.assertj.core.api.Assertions.assertThat;

import org.junit.jupiter.api.Test;

class HeardSurfacesTest {
    private final HeardSurfaces heard = new HeardSurfaces();

    @Test
    void aSurfaceIsHeardOnceByEqualityNotIdentity() {
        assertThat(heard.firstFrom(new Struck.OtherBall("B1"))).isTrue();
        assertThat(heard.firstFrom(new Struck.OtherBall("B1"))).isFalse();
        assertThat(heard.firstFrom(new TriggerSource.OfGizmo("B1"))).as("a gizmo of the same name is another").isTrue();
    }

    @Test
    void namesWhoseHashesCollideAreStillTwo() {
        assertThat("Aa".hashCode()).isEqualTo("BB".hashCode());
        assertThat(new Struck.OtherBall("Aa").hashCode()).isEqualTo(new Struck.OtherBall("BB").hashCode());
        assertThat(heard.firstFrom(new Struck.OtherBall("Aa"))).isTrue();
        assertThat(heard.firstFrom(new Struck.OtherBall("BB"))).isTrue();
        assertThat(heard.firstFrom(new Struck.OtherBall("BB"))).isFalse();
    }

    @Test
    void itGrowsPastItsFirstRoomAndForgetsAtClear() {
        for (int i = 0; i < 40; i++) {
            assertThat(heard.firstFrom(new Struck.OtherBall("B" + i))).isTrue();
        }
        for (int i = 0; i < 40; i++) {
            assertThat(heard.firstFrom(new Struck.OtherBall("B" + i))).isFalse();
        }
        heard.clear();
        assertThat(heard.firstFrom(new Struck.OtherBall("B7"))).isTrue();
    }
}
