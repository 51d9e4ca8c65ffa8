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

	private StatechartSources.Source source;
	private Model model;
	private EditingDomain domain;
	/** Set while the session's own command runs: other changes of the command stack come from elsewhere. */
	private boolean ownChange;
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

	public StatechartSources.Source getSource() {
		return source;
	}

	/** Opens a model: the domain's command stack becomes the session's. */
	public void open(Path file, StatechartSources.Source source, DiagramLayout layout) {
		this.file = file;
		this.source = source;
		this.model = source.model();
		this.domain = source.domain();
		this.layout = layout;
		setCommandStack(domain.getCommandStack());
	}

	/**
	 * Takes up the stack without touching the one before. GLSP's flushes the previous stack, but
	 * that stack is the file's, shared with the other pages (and with the page that comes back
	 * after a dropped connection): a page asking for its model again wiped every page's undo
	 * history and made unsaved edits look saved.
	 */
	@Override
	protected void setCommandStack(org.eclipse.emf.common.command.CommandStack stack) {
		commandStack = stack;
	}

	/**
	 * Reads the model where it may be read ({@link StatechartSources.Source#access}: a workbench's
	 * UI thread, which edits it too), and returns what {@code reading} returns.
	 */
	public <T> T read(java.util.function.Supplier<T> reading) {
		return source == null ? reading.get() : source.access(reading);
	}

	/** Whether the command stack is changing because of this session's own edit, undo or redo. */
	public boolean isOwnChange() {
		return ownChange;
	}

	@Override
	public void execute(org.eclipse.emf.common.command.Command command) {
		own(() -> super.execute(command));
	}

	@Override
	public void undo() {
		own(super::undo);
	}

	@Override
	public void redo() {
		own(super::redo);
	}

	private void own(Runnable change) {
		source.access(() -> {
			ownChange = true;
			try {
				change.run();
			} finally {
				ownChange = false;
			}
			return null;
		});
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
