/** The entry point, {@link gizmoball.Main}: the window or the headless runner. */
package gizmoball;
