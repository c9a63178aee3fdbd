/** Our implementation of the MIT 6.170 physics API: vectors, angles, shapes and the times until they collide. */
package physics;
