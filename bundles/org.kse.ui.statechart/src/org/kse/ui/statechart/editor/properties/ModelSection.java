package org.kse.ui.statechart.editor.properties;

import org.eclipse.emf.edit.command.AddCommand;
import org.eclipse.emf.edit.command.DeleteCommand;
import org.eclipse.jface.layout.GridDataFactory;
import org.eclipse.jface.layout.GridLayoutFactory;
import org.eclipse.jface.viewers.ArrayContentProvider;
import org.eclipse.jface.viewers.CellEditor;
import org.eclipse.jface.viewers.ColumnLabelProvider;
import org.eclipse.jface.viewers.EditingSupport;
import org.eclipse.jface.viewers.IStructuredSelection;
import org.eclipse.jface.viewers.TableViewer;
import org.eclipse.jface.viewers.TableViewerColumn;
import org.eclipse.jface.viewers.TextCellEditor;
import org.eclipse.swt.SWT;
import org.eclipse.swt.widgets.Button;
import org.eclipse.swt.widgets.Composite;
import org.eclipse.swt.widgets.Text;
import org.eclipse.ui.views.properties.tabbed.TabbedPropertySheetPage;
import org.kse.model.statechart.Model;
import org.kse.model.statechart.StatechartFactory;
import org.kse.model.statechart.StatechartPackage.Literals;
import org.kse.model.statechart.Variable;

/**
 * The "Model" tab: the model's name and its variables, the messages that BASIC states' activities
 * read (name and {@code topic.Kind.Message}); a removed variable leaves every state that used it.
 */
public class ModelSection extends ElementSection<Model> {

	private Text name;
	private TableViewer variables;
	private Button remove;

	public ModelSection() {
		super(Model.class);
	}

	@Override
	public void createControls(Composite parent, TabbedPropertySheetPage page) {
		Composite body = body(parent, page);
		name = text(body, "Name:", value -> set(element, Literals.MODEL__NAME, value));
		getWidgetFactory().createLabel(body, "Variables:").setLayoutData(GridDataFactory.fillDefaults().align(SWT.BEGINNING, SWT.BEGINNING).create());
		Composite box = getWidgetFactory().createComposite(body);
		GridLayoutFactory.fillDefaults().numColumns(2).applyTo(box);
		GridDataFactory.fillDefaults().grab(true, true).applyTo(box);
		variables = new TableViewer(box, SWT.BORDER | SWT.FULL_SELECTION | SWT.V_SCROLL);
		variables.getTable().setHeaderVisible(true);
		variables.getTable().setLinesVisible(true);
		GridDataFactory.fillDefaults().grab(true, true).hint(360, 90).applyTo(variables.getControl());
		variables.setContentProvider(ArrayContentProvider.getInstance());
		column("Name", 140, Literals.VARIABLE__NAME);
		column("Message (topic.Kind.Message)", 260, Literals.VARIABLE__TYPE);
		Composite buttons = getWidgetFactory().createComposite(box);
		GridLayoutFactory.fillDefaults().applyTo(buttons);
		GridDataFactory.fillDefaults().align(SWT.BEGINNING, SWT.BEGINNING).applyTo(buttons);
		Button add = getWidgetFactory().createButton(buttons, "Add", SWT.PUSH);
		GridDataFactory.fillDefaults().applyTo(add);
		add.addListener(SWT.Selection, event -> addVariable());
		remove = getWidgetFactory().createButton(buttons, "Remove", SWT.PUSH);
		GridDataFactory.fillDefaults().applyTo(remove);
		remove.addListener(SWT.Selection, event -> removeVariable());
		variables.addSelectionChangedListener(event -> remove.setEnabled(!event.getSelection().isEmpty()));
	}

	private void column(String title, int width, org.eclipse.emf.ecore.EAttribute feature) {
		TableViewerColumn column = new TableViewerColumn(variables, SWT.NONE);
		column.getColumn().setText(title);
		column.getColumn().setWidth(width);
		column.setLabelProvider(new ColumnLabelProvider() {
			@Override
			public String getText(Object element) {
				Object value = ((Variable) element).eGet(feature);
				return value == null ? "" : value.toString();
			}
		});
		column.setEditingSupport(new EditingSupport(variables) {
			@Override
			protected CellEditor getCellEditor(Object element) {
				return new TextCellEditor(variables.getTable());
			}

			@Override
			protected boolean canEdit(Object element) {
				return true;
			}

			@Override
			protected Object getValue(Object element) {
				Object value = ((Variable) element).eGet(feature);
				return value == null ? "" : value.toString();
			}

			@Override
			protected void setValue(Object element, Object value) {
				set((Variable) element, feature, value);
			}
		});
	}

	/** Adds a variable, named so that it is not taken yet, for the user to rename. */
	public Variable addVariable() {
		Variable variable = StatechartFactory.eINSTANCE.createVariable();
		int number = element.getVariables().size() + 1;
		while (taken("variable" + number)) {
			number++;
		}
		variable.setName("variable" + number);
		variable.setType("behavior.State.Message");
		execute(AddCommand.create(domain(), element, Literals.MODEL__VARIABLES, variable));
		variables.editElement(variable, 0);
		return variable;
	}

	private boolean taken(String candidate) {
		return element.getVariables().stream().anyMatch(each -> candidate.equals(each.getName()));
	}

	private void removeVariable() {
		Object selected = ((IStructuredSelection) variables.getSelection()).getFirstElement();
		if (selected instanceof Variable variable) {
			// DeleteCommand also takes the variable out of every state that reads it
			execute(DeleteCommand.create(domain(), variable));
		}
	}

	@Override
	protected void fill() {
		show(name, element.getName());
		variables.setInput(element.getVariables().toArray());
		remove.setEnabled(!variables.getSelection().isEmpty());
	}
}
