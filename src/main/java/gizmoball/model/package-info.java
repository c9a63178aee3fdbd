/**
 * The Gizmoball board without any Swing: gizmos, balls, connections, key bindings, the editing operations and play
 * (docs/design.md, "The board"). It may use the loop of play ({@code gizmoball.model.loop}) and the gizmo kinds
 * ({@code gizmoball.model.gizmo}), neither of which may use this package, {@code physics} (only the listed API) and
 * the JDK; no AWT, no Swing.
 *
 * <p>{@link gizmoball.model.Board} holds everything and is the only way to change it, a facade over parts with one
 * job each: {@code Registry} (the gizmos and balls by name), {@code PlacementRules} (bounds, overlaps, names),
 * {@code Edits} (the editing operations on gizmos and balls), {@code Wiring} (connections and key bindings),
 * {@code Play} (keys, triggers, firing, capture; what each gizmo does when driven is its own {@code act}) and
 * {@code Observers}. A connection's source and what a ball hit are types ({@link gizmoball.model.loop.TriggerSource},
 * {@link gizmoball.model.loop.Struck}), not names. Every editing operation is checked on a copy of the gizmo first,
 * so it either succeeds completely (observers hear EDIT) or throws {@link gizmoball.model.BoardEditException} and
 * leaves the board untouched. Gizmo shapes (physics-lib segments and circles, zero-radius circles at polygon
 * corners) are built when a gizmo is placed, moved or rotated; a flipper's shapes at both stops are built then too.
 * A 20x20 grid of cells maps each cell to the gizmo covering it: it refuses overlaps when editing and, as the
 * spatial index, gives collision detection the gizmos a ball can reach in the time considered.
 *
 * <p>{@link gizmoball.model.Board#tick(double)} runs one {@link gizmoball.model.loop.TickRun}, which sees the board
 * only through {@link gizmoball.model.loop.LoopView} and acts on it only through
 * {@link gizmoball.model.loop.LoopActions}, both implemented by one private adapter in the board; the board keeps the
 * tick's {@link gizmoball.model.loop.TickReport} and notifies the observers.
 */
package gizmoball.model;
