package org.kse.ui.statechart.editor.properties;

import java.util.Arrays;

import org.eclipse.emf.edit.command.AddCommand;
import org.eclipse.emf.edit.command.RemoveCommand;
import org.eclipse.jface.layout.GridDataFactory;
import org.eclipse.jface.viewers.ArrayContentProvider;
import org.eclipse.jface.viewers.CheckboxTableViewer;
import org.eclipse.jface.viewers.LabelProvider;
import org.eclipse.swt.SWT;
import org.eclipse.swt.custom.CCombo;
import org.eclipse.swt.widgets.Composite;
import org.eclipse.swt.widgets.Text;
import org.eclipse.ui.views.properties.tabbed.TabbedPropertySheetPage;
import org.kse.model.NodeKind;
import org.kse.model.statechart.Model;
import org.kse.model.statechart.Node;
import org.kse.model.statechart.StatechartPackage.Literals;
import org.kse.model.statechart.Variable;

/** The "State" tab: name, label, type, activity (BASIC states) and the variables its activity reads. */
public class StateSection extends ElementSection<Node> {

	static final String[] KINDS = Arrays.stream(NodeKind.values()).map(Enum::name).toArray(String[]::new);

	private Text name;
	private Text label;
	private CCombo type;
	private Text activity;
	private CheckboxTableViewer variables;

	public StateSection() {
		super(Node.class);
	}

	@Override
	public void createControls(Composite parent, TabbedPropertySheetPage page) {
		Composite body = body(parent, page);
		name = text(body, "Name:", value -> set(element, Literals.NODE__NAME, value));
		label = text(body, "Label:", value -> set(element, Literals.NODE__LABEL, value));
		getWidgetFactory().createLabel(body, "Type:");
		type = getWidgetFactory().createCCombo(body, SWT.READ_ONLY | SWT.BORDER);
		type.setItems(KINDS);
		type.addListener(SWT.Selection, event -> {
			set(element, Literals.NODE__TYPE, type.getText());
		});
		activity = text(body, "Activity:", value -> set(element, Literals.NODE__ACTIVITY, value));
		activity.setToolTipText("BASIC states: the activity's implementation in the source folder (empty: the state's name)");
		getWidgetFactory().createLabel(body, "Variables:").setLayoutData(GridDataFactory.fillDefaults().align(SWT.BEGINNING, SWT.BEGINNING).create());
		variables = CheckboxTableViewer.newCheckList(body, SWT.BORDER | SWT.V_SCROLL);
		GridDataFactory.fillDefaults().grab(true, true).hint(240, 80).applyTo(variables.getControl());
		variables.setContentProvider(ArrayContentProvider.getInstance());
		variables.setLabelProvider(new LabelProvider() {
			@Override
			public String getText(Object element) {
				Variable variable = (Variable) element;
				return variable.getName() + " : " + variable.getType();
			}
		});
		variables.getTable().setToolTipText("The messages the activity reads (the model's variables, kept in the Model tab)");
		variables.addCheckStateListener(event -> {
			if (refreshing || element == null) {
				return;
			}
			Variable variable = (Variable) event.getElement();
			execute(event.getChecked() ? AddCommand.create(domain(), element, Literals.NODE__VARIABLES, variable)
					: RemoveCommand.create(domain(), element, Literals.NODE__VARIABLES, variable));
		});
	}

	@Override
	protected void fill() {
		show(name, element.getName());
		show(label, element.getLabel());
		type.setText(element.getType() == null ? "" : element.getType());
		show(activity, element.getActivity());
		activity.setEnabled(NodeKind.BASIC.name().equals(element.getType()));
		Model model = editor.getModel();
		variables.setInput(model.getVariables().toArray());
		variables.setCheckedElements(element.getVariables().toArray());
	}
}
