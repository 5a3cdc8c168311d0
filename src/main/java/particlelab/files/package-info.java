/**
 * How the app writes the files a user asks for (exports, screenshots, the report): created
 * new, never through a symbolic link, an existing file replaced only when the user says so.
 * Imports only the JDK, so every package may use it.
 */
package particlelab.files;
