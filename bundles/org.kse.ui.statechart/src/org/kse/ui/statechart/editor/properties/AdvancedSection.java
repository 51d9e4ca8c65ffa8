package org.kse.ui.statechart.editor.properties;

import org.eclipse.emf.ecore.EObject;
import org.eclipse.jface.layout.GridDataFactory;
import org.eclipse.jface.layout.GridLayoutFactory;
import org.eclipse.jface.viewers.ISelection;
import org.eclipse.swt.widgets.Composite;
import org.eclipse.ui.IWorkbenchPart;
import org.eclipse.ui.views.properties.PropertySheetPage;
import org.eclipse.ui.views.properties.tabbed.TabbedPropertySheetPage;

/** The "Advanced" tab: every attribute of the element in the classic property table (EMF's descriptors). */
public class AdvancedSection extends ElementSection<EObject> {

	private PropertySheetPage table;

	public AdvancedSection() {
		super(EObject.class);
	}

	@Override
	public void createControls(Composite parent, TabbedPropertySheetPage page) {
		super.createControls(parent, page);
		Composite body = getWidgetFactory().createFlatFormComposite(parent);
		GridLayoutFactory.fillDefaults().applyTo(body);
		table = new PropertySheetPage();
		table.createControl(body);
		GridDataFactory.fillDefaults().grab(true, true).hint(480, 160).applyTo(table.getControl());
	}

	@Override
	public void setInput(IWorkbenchPart part, ISelection selection) {
		super.setInput(part, selection);
		if (editor != null && table != null) {
			table.setPropertySourceProvider(object -> object instanceof EObject element ? editor.propertySource(element) : null);
			table.selectionChanged(part, selection);
		}
	}

	@Override
	protected void fill() {
		if (table != null) {
			table.refresh();
		}
	}

	@Override
	public boolean shouldUseExtraSpace() {
		return true;
	}

	@Override
	public void dispose() {
		// sections are made for every tab but their controls only when their tab is first shown
		if (table != null) {
			table.dispose();
		}
		super.dispose();
	}
}
