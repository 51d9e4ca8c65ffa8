package org.kse.simulation;

/** A simulation that cannot be built, started or go on; the message says why, for the user. */
public class SimulationException extends Exception {
	private static final long serialVersionUID = 1L;

	public SimulationException(String message) {
		super(message);
	}

	public SimulationException(String message, Throwable cause) {
		super(message, cause);
	}
}
