package org.kse.ui.statechart.editor.properties;

import java.util.ArrayList;
import java.util.List;

import org.eclipse.emf.ecore.EObject;
import org.eclipse.jface.layout.GridDataFactory;
import org.eclipse.swt.SWT;
import org.eclipse.swt.custom.CCombo;
import org.eclipse.swt.widgets.Composite;
import org.eclipse.swt.widgets.Label;
import org.eclipse.swt.widgets.Text;
import org.eclipse.ui.views.properties.tabbed.TabbedPropertySheetPage;
import org.kse.model.statechart.Node;
import org.kse.model.statechart.StatechartPackage.Literals;
import org.kse.model.statechart.Transition;
import org.kse.ui.statechart.editor.ExpressionField;

/**
 * The "Transition" tab: name, source, target, and the expression in a field of several lines,
 * checked while typed and completed on Ctrl+Space; the expression is set when the field loses
 * the focus (or another element is shown), as one command.
 */
public class TransitionSection extends ElementSection<Transition> {

	private Text name;
	private CCombo source;
	private CCombo target;
	private ExpressionField expression;
	private Label problem;
	/** The user typed in the expression since it was filled. */
	private boolean expressionEdited;
	private final List<Node> states = new ArrayList<>();

	public TransitionSection() {
		super(Transition.class);
	}

	@Override
	public void createControls(Composite parent, TabbedPropertySheetPage page) {
		Composite body = body(parent, page);
		name = text(body, "Name:", value -> set(element, Literals.TRANSITION__NAME, value));
		source = combo(body, "Source:");
		source.addListener(SWT.Selection, event -> set(element, Literals.TRANSITION__SOURCE, state(source)));
		target = combo(body, "Target:");
		target.addListener(SWT.Selection, event -> set(element, Literals.TRANSITION__TARGET, state(target)));
		getWidgetFactory().createLabel(body, "Expression:").setLayoutData(GridDataFactory.fillDefaults().align(SWT.BEGINNING, SWT.BEGINNING).create());
		expression = new ExpressionField(body, SWT.BORDER, org.kse.messages.MessageCatalog.of(List.of()), problems -> {
			if (problem != null && !problem.isDisposed()) {
				String summary = ExpressionField.summary(problems);
				problem.setText(summary == null ? "event[condition]/actions; Ctrl+Space completes" : summary);
				problem.setForeground(problem.getDisplay().getSystemColor(summary == null ? SWT.COLOR_DARK_GRAY : SWT.COLOR_RED));
			}
		});
		GridDataFactory.fillDefaults().grab(true, true).hint(360, 90).applyTo(expression.getViewer().getControl());
		expression.onChange(() -> expressionEdited |= !refreshing);
		expression.getViewer().getTextWidget().addListener(SWT.FocusOut, event -> commitPending());
		getWidgetFactory().createLabel(body, "");
		problem = getWidgetFactory().createLabel(body, "", SWT.WRAP);
		GridDataFactory.fillDefaults().grab(true, false).hint(360, SWT.DEFAULT).applyTo(problem);
	}

	private CCombo combo(Composite body, String label) {
		getWidgetFactory().createLabel(body, label);
		CCombo combo = getWidgetFactory().createCCombo(body, SWT.READ_ONLY | SWT.BORDER);
		GridDataFactory.fillDefaults().grab(true, false).applyTo(combo);
		combo.setVisibleItemCount(20);
		return combo;
	}

	private Node state(CCombo combo) {
		int index = combo.getSelectionIndex();
		return index >= 0 && index < states.size() ? states.get(index) : null;
	}

	@Override
	public void commitPending() {
		super.commitPending();
		if (expressionEdited && element != null && expression != null && !expression.getViewer().getTextWidget().isDisposed()) {
			expressionEdited = false;
			String text = expression.getText();
			String current = element.getTE() == null ? "" : element.getTE();
			if (!text.equals(current)) {
				set(element, Literals.TRANSITION__TE, text);
			}
		}
	}

	@Override
	protected void fill() {
		show(name, element.getName());
		states.clear();
		for (var contents = editor.getModel().eAllContents(); contents.hasNext();) {
			EObject next = contents.next();
			if (next instanceof Node node) {
				states.add(node);
			}
		}
		String[] items = states.stream().map(node -> node.getLabel() + "  " + node.getName()).toArray(String[]::new);
		source.setItems(items);
		source.select(states.indexOf(element.getSource()));
		target.setItems(items);
		target.select(states.indexOf(element.getTarget()));
		expression.setCatalog(editor.catalog());
		expression.setText(element.getTE());
		expressionEdited = false;
	}

	/** The expression field, for tests and for the caret's owner. */
	public ExpressionField getExpression() {
		return expression;
	}
}
