/** The state of one window: the board, the design play starts from, its file, unsaved changes, the mode. */
package gizmoball.session;
