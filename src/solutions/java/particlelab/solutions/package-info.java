/** The reference solutions of the exercises, for lecturers (`gradle grade -Psolutions`). */
package particlelab.solutions;
