/** Build mode without Swing: the tools, the step a tool has half done, previews and undo. */
package gizmoball.editor;
