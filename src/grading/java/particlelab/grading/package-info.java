/** The grader of the exercises: their checks, the table and the score (`gradle grade`). */
package particlelab.grading;
