package gizmoball.model.loop;

/**
 * What a ball hit in stage 4 of a tick: a trigger source (a gizmo or the outer walls), whose connections stage 5
 * then triggers, or another ball, which triggers nothing.
 */
public sealed interface Struck permits TriggerSource, Struck.OtherBall {

    /** The ball named {@code ball}. */
    record OtherBall(String ball) implements Struck {
    }
}
