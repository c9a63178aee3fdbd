/**
 * The Gizmoball board without any Swing: gizmos, balls, connections, key bindings, the editing operations and
 * the six-stage physics loop of SPEC.md.
 *
 * <p>{@link gizmoball.model.Board} holds everything and is the only way to change it. Every editing operation is
 * checked on a copy of the gizmo first, so it either succeeds completely (observers hear EDIT) or throws
 * {@link gizmoball.model.BoardEditException} and leaves the board untouched. Gizmo shapes (physics-lib segments
 * and circles, zero-radius circles at polygon corners) are built when a gizmo is placed, moved or rotated. A
 * 20x20 grid of cells maps each cell to the gizmo covering it: it refuses overlaps when editing and, as the
 * spatial index, gives collision detection the gizmos a ball can reach in the time considered.
 *
 * <p>{@code TickRun} runs one tick: friction and gravity, then detection, motion to the first collision,
 * resolution and triggering repeat until the tick is used up (CONTINUOUS) or, in SEED, until each ball has had
 * its one collision; then the observers are notified.
 */
package gizmoball.model;
