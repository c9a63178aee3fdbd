/** The composition root: builds the session, window, loop, commands and features and wires them together. */
package gizmoball.app;
