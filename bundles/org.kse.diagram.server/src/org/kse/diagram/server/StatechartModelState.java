package org.kse.diagram.server;

import java.nio.file.Path;
import java.util.HashMap;
import java.util.Map;

import org.eclipse.emf.ecore.EObject;
import org.eclipse.emf.edit.domain.EditingDomain;
import org.eclipse.glsp.server.model.DefaultGModelState;
import org.kse.model.statechart.Model;

/**
 * A client session's statechart: the model and the editing domain whose command stack holds
 * every edit (the diagram's undo and redo are the model's), where its states are drawn, the file
 * it came from, and which model element each diagram id stands for.
 */
public class StatechartModelState extends DefaultGModelState {

	private Model model;
	private EditingDomain domain;
	private DiagramLayout layout;
	private Path file;
	private final Map<String, EObject> elements = new HashMap<>();

	public Model getModel() {
		return model;
	}

	public EditingDomain getDomain() {
		return domain;
	}

	public DiagramLayout getLayout() {
		return layout;
	}

	public Path getFile() {
		return file;
	}

	/** Opens a model: the domain's command stack becomes the session's. */
	public void open(Path file, Model model, EditingDomain domain, DiagramLayout layout) {
		this.file = file;
		this.model = model;
		this.domain = domain;
		this.layout = layout;
		setCommandStack(domain.getCommandStack());
	}

	/** The model element (state or transition) behind a diagram id, labels standing for their element; null when unknown. */
	public EObject element(String id) {
		if (id == null) {
			return null;
		}
		int hash = id.indexOf('#');
		return elements.get(hash < 0 ? id : id.substring(0, hash));
	}

	void index(Map<String, EObject> ids) {
		elements.clear();
		elements.putAll(ids);
	}
}
