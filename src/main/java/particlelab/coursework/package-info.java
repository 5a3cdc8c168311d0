/**
 * The contracts of the student exercises (docs/exercises.md): one interface per slide's code, so
 * a student's class, a reference solution and a mutant are graded by the same checks.
 */
package particlelab.coursework;
