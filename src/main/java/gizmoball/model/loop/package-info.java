/**
 * Balls and the six-stage loop of play (docs/design.md, "The tick"): {@link gizmoball.model.loop.TickRun} runs one
 * tick, friction and gravity (less what presses into the persistent contacts that {@code Contacts} keeps, named by
 * {@code ContactRef}), then detection ({@code CollisionSchedule}, {@code CollisionDetector}, {@code BallGrid} and the
 * gizmos' {@link gizmoball.model.loop.SpatialIndex}), motion to the first collision, resolution (with
 * {@code Squeeze} for pinched balls) and triggering, repeated until the tick is used up; sleeping balls
 * ({@link gizmoball.model.loop.Sleepers}) are left alone; it returns the {@link gizmoball.model.loop.TickReport}.
 * Here too is what the loop and the board both speak of: the {@link gizmoball.model.loop.Ball}, a
 * {@link gizmoball.model.loop.Connection} from a {@link gizmoball.model.loop.TriggerSource}, what a ball
 * {@link gizmoball.model.loop.Struck}, the {@link gizmoball.model.loop.PlayEvent}s, the
 * {@link gizmoball.model.loop.Arena}'s measures and every {@link gizmoball.model.loop.Tolerances tolerance}.
 *
 * <p>May use: the gizmo kinds ({@code gizmoball.model.gizmo}), {@code physics} (only the listed API) and the JDK; no
 * AWT, no Swing, and not {@code gizmoball.model}: the board runs the loop, never the other way round. The loop reads
 * the board only through {@link gizmoball.model.loop.LoopView} and acts on it only through
 * {@link gizmoball.model.loop.LoopActions}, both implemented by the board. The members the board needs beyond what
 * views see (making, moving and capturing balls, the grid of cells, waking sleepers, running a tick) are public
 * because the board is in another package; their Javadoc says they are for the board (and its loop), not for views.
 */
package gizmoball.model.loop;
