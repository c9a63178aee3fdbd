/**
 * The rules of a game on a board, without Swing (docs/design.md, "The game"): what a hit scores
 * ({@link gizmoball.model.game.Points}), the board's {@link gizmoball.model.game.GameRules} (balls per game, drains,
 * the points of gizmos that differ from their kind's, the extra-ball score), and the {@link gizmoball.model.game.Game}
 * in progress: score, balls left, drains, game over, counted in ticks of the board's simulated clock, so that a game
 * replayed from its key presses is the same game bit for bit.
 *
 * <p>May use: the loop's events ({@code gizmoball.model.loop}) and the gizmo kinds ({@code gizmoball.model.gizmo})
 * and the JDK; not {@code gizmoball.model}: the board runs the game after each tick and is reached by it only
 * through {@link gizmoball.model.game.Playfield}. No AWT, no Swing. Views read a game as a
 * {@link gizmoball.model.game.GameProgress}.
 */
package gizmoball.model.game;
