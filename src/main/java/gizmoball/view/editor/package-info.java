/** The Swing views of build mode: palette, properties, Edit menu, overlay, edge popup and board input. */
package gizmoball.view.editor;
