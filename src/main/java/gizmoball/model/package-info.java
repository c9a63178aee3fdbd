/**
 * The Gizmoball board without any Swing: gizmos, balls, connections, key bindings, the editing operations and
 * the six-stage physics loop (docs/design.md, "The tick"). It may use the gizmo kinds ({@code gizmoball.model.gizmo},
 * which may not use this package), {@code physics} (only the listed API) and the JDK; no AWT, no Swing.
 *
 * <p>{@link gizmoball.model.Board} holds everything and is the only way to change it, a facade over parts with one
 * job each: {@code Registry} (the gizmos and balls by name), {@code PlacementRules} (bounds, overlaps, names),
 * {@code Edits} (the editing operations on gizmos and balls), {@code Wiring} (connections and key bindings),
 * {@code Play} (keys, triggers, firing, capture; what each gizmo does when driven is its own {@code act}) and
 * {@code Observers}. A connection's source and what a ball hit are types ({@link gizmoball.model.TriggerSource},
 * {@link gizmoball.model.Struck}), not names. Every editing operation is checked on a copy of the gizmo first, so
 * it either succeeds completely (observers hear EDIT) or throws {@link gizmoball.model.BoardEditException} and
 * leaves the board untouched. Gizmo shapes (physics-lib segments and circles, zero-radius circles at polygon
 * corners) are built when a gizmo is placed, moved or rotated; a flipper's shapes at both stops are built then too.
 * A 20x20 grid of cells maps each cell to the gizmo covering it: it refuses overlaps when editing and, as the
 * spatial index, gives collision detection the gizmos a ball can reach in the time considered.
 *
 * <p>{@code TickRun} runs one tick: friction and gravity (less what presses into persistent contacts, which
 * {@code Contacts} keeps), then detection ({@code CollisionSchedule}, {@code CollisionDetector}, {@code BallGrid}),
 * motion to the first collision, resolution and triggering repeat until the tick is used up; sleeping balls
 * ({@code Sleepers}) are left alone; then the {@link gizmoball.model.TickReport} is kept and the observers are
 * notified. {@link gizmoball.model.Tolerances} holds every tolerance of the model and the loader.
 */
package gizmoball.model;
