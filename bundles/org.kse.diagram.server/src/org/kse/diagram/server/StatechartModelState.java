package org.kse.diagram.server;

import java.nio.file.Path;

import org.eclipse.glsp.server.model.DefaultGModelState;
import org.kse.model.statechart.Model;
import org.kse.notation.Notation;

/** A client session's statechart: the model, where its states are drawn, and the files they came from. */
public class StatechartModelState extends DefaultGModelState {

	private Model model;
	private Notation notation;
	private Path file;

	public Model getModel() {
		return model;
	}

	public Notation getNotation() {
		return notation;
	}

	public Path getFile() {
		return file;
	}

	void open(Path file, Model model, Notation notation) {
		this.file = file;
		this.model = model;
		this.notation = notation;
	}
}
