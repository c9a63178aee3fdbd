/**
 * Build mode without Swing: {@link gizmoball.editor.Editor} takes pointer and key events in board coordinates
 * and gives each to the current tool's handler ({@code PlaceGizmoTool}, {@code SelectTool}, ...); what a tool
 * has half done is one {@link gizmoball.editor.PendingStep}. Edits go through the model's editing operations
 * inside the {@link gizmoball.editor.EditHistory} (undo, redo). Also the tools and the previews; gizmo kinds are
 * named as the model names them ({@link gizmoball.model.gizmo.GizmoKind#displayName()}).
 *
 * <p>May use: the model, boardfile's key names, java.awt.event.KeyEvent's key codes. No Swing; the views in
 * gizmoball.view.editor read and drive it.
 */
package gizmoball.editor;
