/** The dense-board fuzz: boards as players build them, and a checker of every tick with geometry of its own. */
package gizmoball.fuzz;
