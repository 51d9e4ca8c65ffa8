package org.kse.scxml;

import java.util.Objects;

/**
 * One thing the SCXML export or import could not carry over faithfully, or wants the user to know.
 *
 * @param severity ERROR when the element cannot be carried over (the export or import then
 *        writes nothing), WARNING when it was carried over but the user should look
 * @param element the element it is about, as the user finds it: a KSE state or transition as
 *        {@code label 'name'} (e.g. {@code 0.2 'MakeAction'}), an SCXML element as its tag and id,
 *        or the document itself
 * @param message what is wrong, in a sentence
 */
public record ScxmlProblem(Severity severity, String element, String message) {

    public enum Severity { ERROR, WARNING }

    public ScxmlProblem {
        Objects.requireNonNull(severity, "severity");
        Objects.requireNonNull(element, "element");
        Objects.requireNonNull(message, "message");
    }

    public static ScxmlProblem error(String element, String message) {
        return new ScxmlProblem(Severity.ERROR, element, message);
    }

    public static ScxmlProblem warning(String element, String message) {
        return new ScxmlProblem(Severity.WARNING, element, message);
    }

    public boolean isError() {
        return severity == Severity.ERROR;
    }

    /** {@code ERROR 0.2 'MakeAction': message}, the form the CLI prints. */
    @Override
    public String toString() {
        return severity + " " + element + ": " + message;
    }
}
