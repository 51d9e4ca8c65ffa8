package org.kse.ui.statechart.editor.properties;

import java.util.Objects;
import java.util.function.Consumer;

import org.eclipse.emf.common.command.Command;
import org.eclipse.emf.ecore.EObject;
import org.eclipse.emf.ecore.EStructuralFeature;
import org.eclipse.emf.edit.command.SetCommand;
import org.eclipse.emf.edit.domain.EditingDomain;
import org.eclipse.jface.layout.GridDataFactory;
import org.eclipse.jface.layout.GridLayoutFactory;
import org.eclipse.jface.viewers.ISelection;
import org.eclipse.jface.viewers.IStructuredSelection;
import org.eclipse.swt.SWT;
import org.eclipse.swt.widgets.Composite;
import org.eclipse.swt.widgets.Text;
import org.eclipse.ui.IWorkbenchPart;
import org.eclipse.ui.views.properties.tabbed.AbstractPropertySection;
import org.eclipse.ui.views.properties.tabbed.TabbedPropertySheetPage;
import org.kse.ui.statechart.editor.StatechartEditor;

/**
 * A tab's section for one element of the statechart editor's model. Its fields change the
 * element through commands on the editor's stack, one command per finished edit (a text field
 * commits when it loses the focus or on Enter), so that each can be undone on its own.
 */
abstract class ElementSection<T extends EObject> extends AbstractPropertySection implements StatechartEditor.PendingEdit {

	private final Class<T> type;
	protected StatechartEditor editor;
	protected T element;
	/** Set while the fields are filled from the model, so that filling them changes nothing. */
	protected boolean refreshing;
	private final java.util.Map<Text, Consumer<String>> fields = new java.util.LinkedHashMap<>();
	/** The fields the user typed in since they were filled: only those are handed over, never a stale value. */
	private final java.util.Set<Text> edited = new java.util.HashSet<>();

	ElementSection(Class<T> type) {
		this.type = type;
	}

	@Override
	public void setInput(IWorkbenchPart part, ISelection selection) {
		commitPending();
		super.setInput(part, selection);
		editor = part instanceof StatechartEditor statechartEditor ? statechartEditor : part.getAdapter(StatechartEditor.class);
		Object first = selection instanceof IStructuredSelection structured ? structured.getFirstElement() : null;
		element = type.isInstance(first) ? type.cast(first) : null;
	}

	@Override
	public void aboutToBeHidden() {
		commitPending();
	}

	/** Makes the edit still in a field (a text being typed) before the section shows another element, or on Save. */
	@Override
	public void commitPending() {
		if (element != null && !refreshing) {
			fields.keySet().forEach(this::commit);
		}
	}

	@Override
	public final void refresh() {
		if (element == null || editor == null) {
			return;
		}
		refreshing = true;
		try {
			edited.clear();
			fill();
		} finally {
			refreshing = false;
		}
	}

	/** Fills the fields from the element. */
	protected abstract void fill();

	protected EditingDomain domain() {
		return editor.getEditingDomain();
	}

	/** Sets a feature of an object as a command, when it changes anything. */
	protected void set(EObject object, EStructuralFeature feature, Object value) {
		if (refreshing || object == null || Objects.equals(object.eGet(feature), value)) {
			return;
		}
		execute(SetCommand.create(domain(), object, feature, value));
	}

	protected void execute(Command command) {
		if (command.canExecute()) {
			domain().getCommandStack().execute(command);
		}
	}

	protected Composite body(Composite parent, TabbedPropertySheetPage page) {
		super.createControls(parent, page);
		Composite body = getWidgetFactory().createFlatFormComposite(parent);
		GridLayoutFactory.swtDefaults().numColumns(2).spacing(8, 6).applyTo(body);
		return body;
	}

	/** A labelled one-line text field that hands its text over on Enter and when it loses the focus. */
	protected Text text(Composite body, String label, Consumer<String> commit) {
		getWidgetFactory().createLabel(body, label);
		Text text = getWidgetFactory().createText(body, "");
		GridDataFactory.fillDefaults().grab(true, false).hint(240, SWT.DEFAULT).applyTo(text);
		fields.put(text, commit);
		text.addListener(SWT.Modify, event -> {
			if (!refreshing) {
				edited.add(text);
			}
		});
		text.addListener(SWT.DefaultSelection, event -> commit(text));
		text.addListener(SWT.FocusOut, event -> commit(text));
		return text;
	}

	private void commit(Text text) {
		if (edited.remove(text) && !text.isDisposed() && element != null) {
			fields.get(text).accept(text.getText());
		}
	}

	protected static void show(Text text, String value) {
		String shown = value == null ? "" : value;
		if (!text.getText().equals(shown)) {
			text.setText(shown);
		}
	}
}
