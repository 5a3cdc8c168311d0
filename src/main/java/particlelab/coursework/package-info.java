/**
 * The contracts of the student exercises (docs/exercises.md): one interface per slide's code, so
 * a student's class, a reference solution and a mutant are graded by the same checks; and the
 * runner that calls a student's class in the window, where nothing it does may stop the app.
 */
package particlelab.coursework;
