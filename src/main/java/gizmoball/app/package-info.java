/**
 * The composition root: {@link gizmoball.app.Gizmoball} builds the session, the window and its views, the game
 * loop, the file commands, key forwarding, build mode ({@link gizmoball.app.BuildModeInstaller}) and the play
 * features (speed, sound, trails, settings: {@link gizmoball.app.PlayFeatures}), and wires them together.
 *
 * <p>May use every other package of the game. Nothing imports it but {@code gizmoball.Main} and the tests.
 */
package gizmoball.app;
