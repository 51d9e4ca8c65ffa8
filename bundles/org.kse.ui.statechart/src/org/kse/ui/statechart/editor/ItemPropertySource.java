package org.kse.ui.statechart.editor;

import java.util.ArrayList;
import java.util.List;

import org.eclipse.emf.common.notify.AdapterFactory;
import org.eclipse.emf.ecore.EAttribute;
import org.eclipse.emf.ecore.EObject;
import org.eclipse.emf.ecore.EStructuralFeature;
import org.eclipse.emf.edit.command.SetCommand;
import org.eclipse.emf.edit.domain.EditingDomain;
import org.eclipse.emf.edit.provider.IItemPropertyDescriptor;
import org.eclipse.emf.edit.provider.IItemPropertySource;
import org.eclipse.emf.edit.provider.IItemLabelProvider;
import org.eclipse.ui.views.properties.ComboBoxPropertyDescriptor;
import org.eclipse.ui.views.properties.IPropertyDescriptor;
import org.eclipse.ui.views.properties.IPropertySource;
import org.eclipse.ui.views.properties.PropertyDescriptor;
import org.eclipse.ui.views.properties.TextPropertyDescriptor;
import org.kse.model.NodeKind;
import org.kse.model.statechart.StatechartPackage;

/**
 * A model element's properties in the Properties view (the part of emf.edit.ui KSE cannot have):
 * EMF's item property descriptors shown, every change made as a command on the editor's stack,
 * so that it can be undone.
 */
class ItemPropertySource implements IPropertySource {

	private static final String[] KINDS = java.util.Arrays.stream(NodeKind.values()).map(Enum::name).toArray(String[]::new);

	private final EObject object;
	private final IItemPropertySource source;
	private final EditingDomain domain;
	private final org.kse.messages.MessageCatalog catalog;

	ItemPropertySource(EObject object, AdapterFactory factory, EditingDomain domain, org.kse.messages.MessageCatalog catalog) {
		this.object = object;
		this.catalog = catalog;
		this.source = (IItemPropertySource) factory.adapt(object, IItemPropertySource.class);
		this.domain = domain;
	}

	@Override
	public Object getEditableValue() {
		return object;
	}

	@Override
	public IPropertyDescriptor[] getPropertyDescriptors() {
		List<IPropertyDescriptor> descriptors = new ArrayList<>();
		if (source == null) {
			return new IPropertyDescriptor[0];
		}
		for (IItemPropertyDescriptor item : source.getPropertyDescriptors(object)) {
			Object feature = item.getFeature(object);
			String id = item.getId(object);
			String name = item.getDisplayName(object);
			PropertyDescriptor descriptor;
			if (feature == StatechartPackage.Literals.NODE__TYPE) {
				descriptor = new ComboBoxPropertyDescriptor(id, name, KINDS);
			} else if (feature == StatechartPackage.Literals.TRANSITION__TE) {
				descriptor = new PropertyDescriptor(id, name) {
					@Override
					public org.eclipse.jface.viewers.CellEditor createPropertyEditor(org.eclipse.swt.widgets.Composite parent) {
						return new org.eclipse.jface.viewers.DialogCellEditor(parent) {
							@Override
							protected Object openDialogBox(org.eclipse.swt.widgets.Control window) {
								ExpressionDialog dialog = new ExpressionDialog(window.getShell(),
										org.kse.validation.Labels.describe(object), (String) getValue(), catalog);
								return dialog.open() == org.eclipse.jface.window.Window.OK ? dialog.getValue() : null;
							}
						};
					}
				};
			} else if (item.canSetProperty(object) && feature instanceof EAttribute) {
				descriptor = new TextPropertyDescriptor(id, name);
			} else {
				descriptor = new PropertyDescriptor(id, name);
			}
			descriptor.setDescription(item.getDescription(object));
			descriptor.setCategory(item.getCategory(object));
			descriptor.setLabelProvider(new org.eclipse.jface.viewers.LabelProvider() {
				@Override
				public String getText(Object element) {
					if (element instanceof Integer index && feature == StatechartPackage.Literals.NODE__TYPE) {
						return index >= 0 && index < KINDS.length ? KINDS[index] : "";
					}
					IItemLabelProvider labels = item.getLabelProvider(object);
					return labels == null ? String.valueOf(element) : labels.getText(element);
				}
			});
			descriptors.add(descriptor);
		}
		return descriptors.toArray(IPropertyDescriptor[]::new);
	}

	private IItemPropertyDescriptor item(Object id) {
		return source == null ? null : source.getPropertyDescriptor(object, id);
	}

	@Override
	public Object getPropertyValue(Object id) {
		IItemPropertyDescriptor item = item(id);
		if (item == null) {
			return null;
		}
		Object value = item.getPropertyValue(object);
		if (value instanceof IItemPropertySource wrapped) {
			value = wrapped.getEditableValue(object);
		}
		if (item.getFeature(object) == StatechartPackage.Literals.NODE__TYPE) {
			return java.util.Arrays.asList(KINDS).indexOf(value);
		}
		return value == null ? "" : value;
	}

	@Override
	public boolean isPropertySet(Object id) {
		IItemPropertyDescriptor item = item(id);
		return item != null && item.isPropertySet(object);
	}

	@Override
	public void resetPropertyValue(Object id) {
		// values are never reset to a default from the Properties view
	}

	@Override
	public void setPropertyValue(Object id, Object value) {
		IItemPropertyDescriptor item = item(id);
		if (item == null || !(item.getFeature(object) instanceof EStructuralFeature feature)) {
			return;
		}
		Object newValue = feature == StatechartPackage.Literals.NODE__TYPE && value instanceof Integer index ? KINDS[index] : value;
		if (java.util.Objects.equals(object.eGet(feature), newValue)) {
			return;
		}
		domain.getCommandStack().execute(SetCommand.create(domain, object, feature, newValue));
	}
}
