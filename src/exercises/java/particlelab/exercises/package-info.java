/** The exercises a student writes (docs/exercises.md); `gradle grade` grades them. */
package particlelab.exercises;
