/** Board files: reading them with clear errors, writing them safely, and the words and numbers they use. */
package gizmoball.boardfile;
