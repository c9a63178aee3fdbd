/**
 * The entry point ({@link gizmoball.Main}): the window through gizmoball.app, or the headless runner.
 * docs/design.md describes the packages and how they depend on each other.
 */
package gizmoball;
