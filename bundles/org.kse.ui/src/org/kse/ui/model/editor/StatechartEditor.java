package org.kse.ui.model.editor;

import java.io.IOException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;

import org.eclipse.core.resources.IFile;
import org.eclipse.core.resources.IResource;
import org.eclipse.core.runtime.CoreException;
import org.eclipse.core.runtime.IProgressMonitor;
import org.eclipse.emf.common.command.BasicCommandStack;
import org.eclipse.emf.common.command.CommandStack;
import org.eclipse.emf.common.command.CommandStackListener;
import org.eclipse.emf.ecore.EObject;
import org.eclipse.emf.edit.domain.AdapterFactoryEditingDomain;
import org.eclipse.emf.edit.domain.EditingDomain;
import org.eclipse.emf.edit.domain.IEditingDomainProvider;
import org.eclipse.emf.edit.provider.ComposedAdapterFactory;
import org.eclipse.emf.edit.provider.ReflectiveItemProviderAdapterFactory;
import org.eclipse.emf.edit.provider.resource.ResourceItemProviderAdapterFactory;
import org.eclipse.jface.action.Action;
import org.eclipse.jface.viewers.ColumnLabelProvider;
import org.eclipse.jface.viewers.ITreeContentProvider;
import org.eclipse.jface.viewers.StructuredSelection;
import org.eclipse.jface.viewers.TreeViewer;
import org.eclipse.swt.SWT;
import org.eclipse.swt.graphics.Color;
import org.eclipse.swt.widgets.Composite;
import org.eclipse.ui.IEditorInput;
import org.eclipse.ui.IEditorSite;
import org.eclipse.ui.PartInitException;
import org.eclipse.ui.actions.ActionFactory;
import org.eclipse.ui.part.EditorPart;
import org.eclipse.ui.views.properties.IPropertySheetPage;
import org.eclipse.ui.views.properties.PropertySheetPage;
import org.kse.model.StatechartResources;
import org.kse.model.statechart.Model;
import org.kse.model.statechart.Node;
import org.kse.model.statechart.Transition;

/**
 * The statechart as a tree (states nested as in the file, then the transitions) with its
 * properties in the Properties view. Every edit is a command: undo, redo and the dirty state
 * follow the command stack; Save writes the file atomically.
 */
public class StatechartEditor extends EditorPart implements IEditingDomainProvider {

	public static final String ID = "org.kse.ui.statechart.editor";

	/** The tree's folder of transitions under the model. */
	public record Transitions(Model model) {
	}

	private static final Color STATE = new Color(0x1f, 0x4e, 0x9c);
	private static final Color TRANSITION = new Color(0x55, 0x55, 0x55);

	private ComposedAdapterFactory adapterFactory;
	private AdapterFactoryEditingDomain domain;
	private Model model;
	private TreeViewer viewer;
	private final CommandStackListener stackListener = event -> getSite().getShell().getDisplay().asyncExec(this::stackChanged);
	private Action undo;
	private Action redo;
	private final List<PropertySheetPage> sheets = new ArrayList<>();
	private org.kse.messages.MessageCatalog catalog;
	private String catalogFolder;

	@Override
	public void init(IEditorSite site, IEditorInput input) throws PartInitException {
		setSite(site);
		setInput(input);
		setPartName(input.getName());
		adapterFactory = new ComposedAdapterFactory(ComposedAdapterFactory.Descriptor.Registry.INSTANCE);
		adapterFactory.addAdapterFactory(new ResourceItemProviderAdapterFactory());
		adapterFactory.addAdapterFactory(new ReflectiveItemProviderAdapterFactory());
		BasicCommandStack stack = new BasicCommandStack();
		domain = new AdapterFactoryEditingDomain(adapterFactory, stack);
		IFile file = getFile();
		if (file == null) {
			throw new PartInitException("the statechart editor opens files of the workspace");
		}
		try {
			model = StatechartResources.load(domain.getResourceSet(), Path.of(file.getLocationURI()));
		} catch (IOException e) {
			throw new PartInitException("cannot open " + file.getFullPath() + ": " + e.getMessage(), e);
		}
		stack.addCommandStackListener(stackListener);
		undo = new Action("Undo") {
			@Override
			public void run() {
				domain.getCommandStack().undo();
			}
		};
		redo = new Action("Redo") {
			@Override
			public void run() {
				domain.getCommandStack().redo();
			}
		};
		site.getActionBars().setGlobalActionHandler(ActionFactory.UNDO.getId(), undo);
		site.getActionBars().setGlobalActionHandler(ActionFactory.REDO.getId(), redo);
		updateUndoRedo();
	}

	public IFile getFile() {
		return getEditorInput().getAdapter(IFile.class);
	}

	public Model getModel() {
		return model;
	}

	@Override
	public EditingDomain getEditingDomain() {
		return domain;
	}

	public TreeViewer getViewer() {
		return viewer;
	}

	@Override
	public void createPartControl(Composite parent) {
		viewer = new TreeViewer(parent, SWT.MULTI | SWT.H_SCROLL | SWT.V_SCROLL);
		viewer.setContentProvider(new ITreeContentProvider() {
			@Override
			public Object[] getElements(Object input) {
				List<Object> roots = new ArrayList<>(((Model) input).getNodes());
				roots.add(new Transitions((Model) input));
				return roots.toArray();
			}

			@Override
			public Object[] getChildren(Object element) {
				if (element instanceof Node node) {
					return node.getChildren().toArray();
				}
				if (element instanceof Transitions transitions) {
					return transitions.model().getTransitions().toArray();
				}
				return new Object[0];
			}

			@Override
			public Object getParent(Object element) {
				return element instanceof EObject object ? object.eContainer() : null;
			}

			@Override
			public boolean hasChildren(Object element) {
				return getChildren(element).length > 0;
			}
		});
		viewer.setLabelProvider(new ColumnLabelProvider() {
			@Override
			public String getText(Object element) {
				return label(element);
			}

			@Override
			public Color getForeground(Object element) {
				return element instanceof Transition ? TRANSITION : STATE;
			}
		});
		viewer.setInput(model);
		viewer.expandToLevel(3);
		getSite().setSelectionProvider(viewer);
	}

	/** Opening a validation problem selects the element it is about. */
	private void reveal(org.eclipse.core.resources.IMarker marker) {
		String fragment = marker.getAttribute(org.kse.ui.model.ModelMarkers.ELEMENT, null);
		EObject element = fragment == null || model.eResource() == null ? null : model.eResource().getEObject(fragment);
		if (element != null && viewer != null) {
			viewer.setSelection(new StructuredSelection(element), true);
		}
	}

	/** How an element reads in the tree. */
	public static String label(Object element) {
		if (element instanceof Node node) {
			String activity = node.getActivity() == null || node.getActivity().isBlank() ? "" : "  activity " + node.getActivity();
			return node.getLabel() + "  " + node.getName() + " : " + node.getType() + activity;
		}
		if (element instanceof Transition transition) {
			String te = transition.getTE() == null ? "" : transition.getTE().lines().findFirst().orElse("");
			return transition.getName() + (te.isEmpty() ? "" : "   " + te);
		}
		if (element instanceof Transitions transitions) {
			return "Transitions (" + transitions.model().getTransitions().size() + ")";
		}
		return String.valueOf(element);
	}

	private void stackChanged() {
		if (viewer != null && !viewer.getControl().isDisposed()) {
			viewer.refresh(true);
			Object affected = domain.getCommandStack().getMostRecentCommand() == null ? null
					: domain.getCommandStack().getMostRecentCommand().getAffectedObjects().stream().findFirst().orElse(null);
			if (affected != null) {
				viewer.setSelection(new StructuredSelection(affected), true);
			}
		}
		sheets.removeIf(sheet -> sheet.getControl() != null && sheet.getControl().isDisposed());
		sheets.stream().filter(sheet -> sheet.getControl() != null).forEach(PropertySheetPage::refresh);
		firePropertyChange(PROP_DIRTY);
		updateUndoRedo();
	}

	private void updateUndoRedo() {
		CommandStack stack = domain.getCommandStack();
		undo.setEnabled(stack.canUndo());
		undo.setText(stack.canUndo() ? "Undo " + stack.getUndoCommand().getLabel() : "Undo");
		redo.setEnabled(stack.canRedo());
		redo.setText(stack.canRedo() ? "Redo " + stack.getRedoCommand().getLabel() : "Redo");
	}

	@Override
	public <T> T getAdapter(Class<T> adapter) {
		if (adapter == IPropertySheetPage.class) {
			PropertySheetPage page = new PropertySheetPage();
			page.setPropertySourceProvider(object -> object instanceof EObject element ? new ItemPropertySource(element, adapterFactory, domain, catalog()) : null);
			sheets.add(page);
			return adapter.cast(page);
		}
		if (adapter == EditingDomain.class) {
			return adapter.cast(domain);
		}
		if (adapter == org.eclipse.ui.ide.IGotoMarker.class) {
			return adapter.cast((org.eclipse.ui.ide.IGotoMarker) this::reveal);
		}
		return super.getAdapter(adapter);
	}

	/**
	 * The message catalog of this model (ModelFiles.catalog), read once per source folder: the
	 * Properties view asks for it at every selection, and reading means parsing .proto files.
	 */
	public org.kse.messages.MessageCatalog catalog() {
		var sourceFolder = org.kse.ui.model.ModelFiles.sourceFolder(getFile());
		String key = sourceFolder == null ? "" : sourceFolder.getFullPath().toString();
		if (catalog == null || !key.equals(catalogFolder)) {
			catalog = org.kse.ui.model.ModelFiles.catalog(getFile());
			catalogFolder = key;
		}
		return catalog;
	}

	/** The Properties view's source of an element of this editor's model; its edits go on the command stack. */
	public org.eclipse.ui.views.properties.IPropertySource propertySource(EObject element) {
		return new ItemPropertySource(element, adapterFactory, domain, catalog());
	}

	@Override
	public boolean isDirty() {
		return ((BasicCommandStack) domain.getCommandStack()).isSaveNeeded();
	}

	@Override
	public void doSave(IProgressMonitor monitor) {
		IFile file = getFile();
		try {
			StatechartResources.save(model, Path.of(file.getLocationURI()));
			((BasicCommandStack) domain.getCommandStack()).saveIsDone();
			file.refreshLocal(IResource.DEPTH_ZERO, monitor);
			firePropertyChange(PROP_DIRTY);
		} catch (IOException | CoreException e) {
			org.eclipse.jface.dialogs.ErrorDialog.openError(getSite().getShell(), "Save", "Cannot save " + file.getFullPath(),
					org.eclipse.core.runtime.Status.error(e.getMessage(), e));
		}
	}

	@Override
	public boolean isSaveAsAllowed() {
		return false;
	}

	@Override
	public void doSaveAs() {
		// one model, one file: Save As would disconnect it from its source folder
	}

	@Override
	public void setFocus() {
		viewer.getControl().setFocus();
	}

	@Override
	public void dispose() {
		domain.getCommandStack().removeCommandStackListener(stackListener);
		adapterFactory.dispose();
		super.dispose();
	}
}
