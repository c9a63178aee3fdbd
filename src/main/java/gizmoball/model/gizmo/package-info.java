/**
 * The gizmo kinds: {@link gizmoball.model.gizmo.Gizmo} (what views see of a gizmo), the common state in
 * {@link gizmoball.model.gizmo.GizmoBase}, one class per kind ({@link gizmoball.model.gizmo.Bumper} for square,
 * circle and triangle, {@link gizmoball.model.gizmo.Flipper}, {@link gizmoball.model.gizmo.Absorber}),
 * {@link gizmoball.model.gizmo.GizmoKind} (footprints, display names, the one factory), the physical
 * {@link gizmoball.model.gizmo.Shape} each builds when placed, moved or rotated, the signed distances to their
 * solid bodies, and their colours ({@link gizmoball.model.gizmo.Rgb}).
 *
 * <p>May use: {@code physics} (only the listed API) and the JDK; no AWT, no Swing, and not {@code gizmoball.model}
 * or {@code gizmoball.model.loop}: the board and its loop use the kinds, never the other way round. What a triggered gizmo does to the board around it goes
 * through {@link gizmoball.model.gizmo.Surroundings}, which the board's play rules implement. The members the board
 * and its loop need beyond what views see (moving, rotating, triggering, a flipper's swing and block, an absorber's
 * held balls) are public because the board is in another package; their Javadoc says they are for the board and
 * its loop, not for views.
 */
package gizmoball.model.gizmo;
