package org.kse.ui.statechart.editor;

import org.kse.model.edit.StatechartEdits;
import java.io.IOException;
import java.nio.file.Path;
import java.nio.file.attribute.FileTime;
import java.util.ArrayList;
import java.util.List;

import org.eclipse.core.resources.IFile;
import org.eclipse.core.resources.IResource;
import org.eclipse.core.resources.IResourceChangeEvent;
import org.eclipse.core.resources.IResourceChangeListener;
import org.eclipse.core.resources.IResourceDelta;
import org.eclipse.core.resources.ResourcesPlugin;
import org.eclipse.core.runtime.CoreException;
import org.eclipse.core.runtime.IProgressMonitor;
import org.eclipse.emf.common.command.BasicCommandStack;
import org.eclipse.emf.common.command.Command;
import org.eclipse.emf.common.command.CommandStack;
import org.eclipse.emf.common.command.CommandStackListener;
import org.eclipse.emf.ecore.EObject;
import org.eclipse.emf.edit.domain.AdapterFactoryEditingDomain;
import org.eclipse.emf.edit.domain.EditingDomain;
import org.eclipse.emf.edit.domain.IEditingDomainProvider;
import org.eclipse.emf.edit.provider.ComposedAdapterFactory;
import org.eclipse.jface.action.Action;
import org.eclipse.jface.action.MenuManager;
import org.eclipse.jface.action.Separator;
import org.eclipse.jface.viewers.ColumnLabelProvider;
import org.eclipse.jface.viewers.IStructuredSelection;
import org.eclipse.jface.viewers.ITreeContentProvider;
import org.eclipse.jface.viewers.StructuredSelection;
import org.eclipse.jface.viewers.TreeViewer;
import org.eclipse.swt.SWT;
import org.eclipse.swt.graphics.Color;
import org.eclipse.swt.widgets.Composite;
import org.eclipse.ui.IEditorInput;
import org.eclipse.ui.IEditorSite;
import org.eclipse.ui.IWorkbenchActionConstants;
import org.eclipse.ui.IWorkbenchCommandConstants;
import org.eclipse.ui.PartInitException;
import org.eclipse.ui.actions.ActionFactory;
import org.eclipse.ui.part.EditorPart;
import org.eclipse.ui.views.properties.IPropertySheetPage;
import org.eclipse.ui.views.properties.tabbed.ITabbedPropertySheetPageContributor;
import org.eclipse.ui.views.properties.tabbed.TabbedPropertySheetPage;
import org.kse.labeling.Copies;
import org.kse.model.NodeKind;
import org.kse.model.StatechartResources;
import org.kse.model.statechart.Model;
import org.kse.model.statechart.Node;
import org.kse.model.statechart.Transition;
import org.kse.ui.ModelFiles;
import org.kse.ui.statechart.KeyEchoes;

/**
 * The statechart as a diagram (Diagram tab: the KSE diagram page in a browser) and as a tree (Tree
 * tab: the model, its states nested as in the file, then the transitions), with the properties of
 * what either selects in the tabbed Properties view. On the tree, states and transitions are added
 * and deleted from the context menu and moved by dragging. Both pages edit one model: every edit
 * is a command on one stack, so undo, redo and the dirty state follow it whichever page made it;
 * Save writes the file (and the diagram's notation beside it) atomically, Revert reloads it, and a
 * file changed on disk is reloaded when the editor has no unsaved changes.
 */
public class StatechartEditor extends EditorPart implements IEditingDomainProvider, ITabbedPropertySheetPageContributor {

	public static final String ID = "org.kse.ui.statechart.editor";

	/** A field of the Properties view that holds an edit until it loses the focus; Save makes it first. */
	public interface PendingEdit {
		void commitPending();
	}

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
	private Action revert;
	private Action delete;
	private Action cut;
	private Action copy;
	private Action paste;
	/** Copied states, shared by the statechart editors so that states can be pasted into another model. */
	private static Copies.Fragment clipboard;
	private final List<TabbedPropertySheetPage> sheets = new ArrayList<>();
	private final IResourceChangeListener fileListener = this::fileChanged;
	/** Set while this editor writes its file, so that its own save is not taken for a change on disk. */
	private boolean saving;
	/** The file on disk as this editor last read, wrote or was told of it: a save over anything else asks first. */
	private FileTime seenOnDisk;
	private org.kse.messages.MessageCatalog catalog;
	private String catalogFolder;
	private org.eclipse.swt.custom.CTabFolder tabs;
	private org.kse.ui.statechart.diagram.DiagramPage diagram;
	/** Set while a selection made on one page is shown on the other, so that it does not come back. */
	private boolean syncingSelection;
	/** What runs after every save: the notation writers of the diagram sessions on this model. */
	private final List<org.kse.diagram.server.StatechartSources.NotationWriter> saveParticipants = new java.util.concurrent.CopyOnWriteArrayList<>();
	private final org.kse.ui.statechart.diagram.WorkspaceDiagramServer.Host diagramHost = new org.kse.ui.statechart.diagram.WorkspaceDiagramServer.Host() {
		@Override
		public Model model() {
			return model;
		}

		@Override
		public EditingDomain domain() {
			return domain;
		}

		@Override
		public void save() {
			doSave(null);
		}

		@Override
		public List<org.kse.diagram.server.StatechartSources.NotationWriter> saveParticipants() {
			return saveParticipants;
		}
	};

	@Override
	public void init(IEditorSite site, IEditorInput input) throws PartInitException {
		setSite(site);
		setInput(input);
		setPartName(input.getName());
		domain = StatechartEdits.newDomain();
		adapterFactory = (ComposedAdapterFactory) domain.getAdapterFactory();
		BasicCommandStack stack = (BasicCommandStack) domain.getCommandStack();
		IFile file = getFile();
		if (file == null) {
			throw new PartInitException("the statechart editor opens files of the workspace");
		}
		try {
			seenOnDisk = lastModified(file);
			model = StatechartResources.load(domain.getResourceSet(), Path.of(file.getLocationURI()));
		} catch (IOException e) {
			throw new PartInitException("cannot open " + file.getFullPath() + ": " + e.getMessage(), e);
		}
		stack.addCommandStackListener(stackListener);
		ResourcesPlugin.getWorkspace().addResourceChangeListener(fileListener, IResourceChangeEvent.POST_CHANGE);
		org.kse.ui.statechart.diagram.WorkspaceDiagramServer.register(Path.of(file.getLocationURI()), diagramHost);
		// one press of Ctrl+Z on the diagram reaches these up to three times (KeyEchoes): it undoes one edit
		undo = new Action("Undo") {
			@Override
			public void run() {
				domain.getCommandStack().undo();
			}

			@Override
			public void runWithEvent(org.eclipse.swt.widgets.Event event) {
				if (!org.kse.ui.statechart.KeyEchoes.isEcho(ActionFactory.UNDO.getCommandId(), event)) {
					run();
				}
			}
		};
		redo = new Action("Redo") {
			@Override
			public void run() {
				domain.getCommandStack().redo();
			}

			@Override
			public void runWithEvent(org.eclipse.swt.widgets.Event event) {
				if (!org.kse.ui.statechart.KeyEchoes.isEcho(ActionFactory.REDO.getCommandId(), event)) {
					run();
				}
			}
		};
		revert = new Action("Revert") {
			@Override
			public void run() {
				doRevert();
			}
		};
		delete = new Action("Delete") {
			@Override
			public void run() {
				execute(StatechartEdits.delete(domain, model, selection().toList()));
			}
		};
		delete.setActionDefinitionId(IWorkbenchCommandConstants.EDIT_DELETE);
		copy = new Action("Copy") {
			@Override
			public void run() {
				copySelection();
			}
		};
		copy.setActionDefinitionId(IWorkbenchCommandConstants.EDIT_COPY);
		cut = new Action("Cut") {
			@Override
			public void run() {
				if (copySelection()) {
					execute(StatechartEdits.delete(domain, model, selectedStates()));
				}
			}
		};
		cut.setActionDefinitionId(IWorkbenchCommandConstants.EDIT_CUT);
		paste = new Action("Paste") {
			@Override
			public void run() {
				execute(StatechartEdits.paste(domain, model, clipboard, selection().getFirstElement()));
			}
		};
		paste.setActionDefinitionId(IWorkbenchCommandConstants.EDIT_PASTE);
		site.getActionBars().setGlobalActionHandler(ActionFactory.UNDO.getId(), undo);
		site.getActionBars().setGlobalActionHandler(ActionFactory.REDO.getId(), redo);
		site.getActionBars().setGlobalActionHandler(ActionFactory.REVERT.getId(), revert);
		site.getActionBars().setGlobalActionHandler(ActionFactory.DELETE.getId(), delete);
		site.getActionBars().setGlobalActionHandler(ActionFactory.CUT.getId(), cut);
		site.getActionBars().setGlobalActionHandler(ActionFactory.COPY.getId(), copy);
		site.getActionBars().setGlobalActionHandler(ActionFactory.PASTE.getId(), paste);
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

	/** The Diagram tab's page. */
	public org.kse.ui.statechart.diagram.DiagramPage getDiagram() {
		return diagram;
	}

	/** Shows the Diagram tab (true) or the Tree tab. */
	public void showDiagram(boolean show) {
		tabs.setSelection(show ? 0 : 1);
		tabChanged();
	}

	public boolean isDiagramShown() {
		return tabs.getSelectionIndex() == 0;
	}

	@Override
	public void createPartControl(Composite parent) {
		tabs = new org.eclipse.swt.custom.CTabFolder(parent, SWT.BOTTOM | SWT.FLAT);
		org.eclipse.swt.custom.CTabItem diagramTab = new org.eclipse.swt.custom.CTabItem(tabs, SWT.NONE);
		diagramTab.setText("Diagram");
		org.eclipse.swt.custom.CTabItem treeTab = new org.eclipse.swt.custom.CTabItem(tabs, SWT.NONE);
		treeTab.setText("Tree");
		createTree(tabs);
		treeTab.setControl(viewer.getControl());
		diagram = new org.kse.ui.statechart.diagram.DiagramPage(tabs, Path.of(getFile().getLocationURI()), () -> model, this::selectedOnDiagram);
		diagramTab.setControl(diagram.getControl());
		tabs.addListener(SWT.Selection, event -> tabChanged());
		showDiagram(diagram.isAvailable());
	}

	/**
	 * The page shown takes the keys: on the diagram, delete, cut, copy and paste are the page's
	 * own (the workbench's would take Delete from the page's text fields); on the tree, the
	 * editor's. Undo, redo and save are the editor's on both: one command stack.
	 */
	private void tabChanged() {
		boolean onTree = !isDiagramShown();
		var bars = getEditorSite().getActionBars();
		bars.setGlobalActionHandler(ActionFactory.DELETE.getId(), onTree ? delete : null);
		bars.setGlobalActionHandler(ActionFactory.CUT.getId(), onTree ? cut : null);
		bars.setGlobalActionHandler(ActionFactory.COPY.getId(), onTree ? copy : null);
		bars.setGlobalActionHandler(ActionFactory.PASTE.getId(), onTree ? paste : null);
		bars.updateActionBars();
	}

	/** Elements selected on the diagram become the editor's selection (the tree's, which the Properties view follows). */
	private void selectedOnDiagram(List<EObject> elements) {
		if (viewer == null || viewer.getControl().isDisposed()) {
			return;
		}
		syncingSelection = true;
		try {
			viewer.setSelection(elements.isEmpty() ? StructuredSelection.EMPTY : new StructuredSelection(elements), true);
		} finally {
			syncingSelection = false;
		}
	}

	private void createTree(Composite parent) {
		viewer = new TreeViewer(parent, SWT.MULTI | SWT.H_SCROLL | SWT.V_SCROLL);
		viewer.setContentProvider(new ITreeContentProvider() {
			@Override
			public Object[] getElements(Object input) {
				// the input is an array around the model: a viewer cannot show its input as an item
				return (Object[]) input;
			}

			@Override
			public Object[] getChildren(Object element) {
				if (element instanceof Model root) {
					List<Object> children = new ArrayList<>(root.getNodes());
					children.add(new Transitions(root));
					return children.toArray();
				}
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
				if (element instanceof Transitions transitions) {
					return transitions.model();
				}
				if (element instanceof Transition transition && transition.eContainer() instanceof Model root) {
					return new Transitions(root);
				}
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
		viewer.setInput(new Object[] { model });
		viewer.expandToLevel(4);
		getSite().setSelectionProvider(viewer);
		viewer.addSelectionChangedListener(event -> updateActions());
		viewer.addSelectionChangedListener(event -> {
			if (!syncingSelection && diagram != null) {
				diagram.select(viewer.getStructuredSelection().toList());
			}
		});
		createContextMenu();
		StructureDragAndDrop.install(this);
		updateActions();
	}

	private IStructuredSelection selection() {
		return viewer == null ? StructuredSelection.EMPTY : viewer.getStructuredSelection();
	}

	private List<Node> selectedStates() {
		List<Node> states = new ArrayList<>();
		for (Object each : selection()) {
			if (each instanceof Node node) {
				states.add(node);
			}
		}
		return states;
	}

	private void createContextMenu() {
		MenuManager menu = new MenuManager("#StatechartEditor");
		menu.setRemoveAllWhenShown(true);
		menu.addMenuListener(manager -> {
			Object first = selection().getFirstElement();
			MenuManager states = new MenuManager("New State");
			for (NodeKind kind : NodeKind.values()) {
				states.add(new Action(kind.name()) {
					@Override
					public void run() {
						execute(StatechartEdits.newState(domain, model, first, kind));
					}
				});
			}
			manager.add(states);
			Action transition = new Action(selectedStates().size() == 2 ? "New Transition (first to second state)" : "New Transition (self-loop)") {
				@Override
				public void run() {
					execute(StatechartEdits.newTransition(domain, model, selectedStates()));
				}
			};
			transition.setEnabled(StatechartEdits.newTransition(domain, model, selectedStates()).canExecute());
			manager.add(transition);
			manager.add(new Separator());
			manager.add(cut);
			manager.add(copy);
			manager.add(paste);
			manager.add(delete);
			manager.add(new Separator(IWorkbenchActionConstants.MB_ADDITIONS));
		});
		viewer.getControl().setMenu(menu.createContextMenu(viewer.getControl()));
		getEditorSite().registerContextMenu(ID, menu, viewer, false);
	}

	/** Copies the selected states (with what they hold, their inner transitions and variables); false when none is selected. */
	private boolean copySelection() {
		List<Node> states = selectedStates();
		if (states.isEmpty()) {
			return false;
		}
		clipboard = Copies.copy(model, states);
		updateActions();
		return true;
	}

	private void updateActions() {
		delete.setEnabled(viewer != null && StatechartEdits.delete(domain, model, selection().toList()).canExecute());
		copy.setEnabled(!selectedStates().isEmpty());
		cut.setEnabled(!selectedStates().isEmpty());
		paste.setEnabled(clipboard != null);
		revert.setEnabled(isDirty());
	}

	/** Runs an edit on the command stack (so that it can be undone); one that cannot run is ignored. */
	public void execute(Command command) {
		if (command.canExecute()) {
			domain.getCommandStack().execute(command);
		}
	}

	/** Opening a validation problem selects the element it is about. */
	private void reveal(org.eclipse.core.resources.IMarker marker) {
		String fragment = marker.getAttribute(org.kse.ui.statechart.ModelMarkers.ELEMENT, null);
		EObject element = fragment == null || model.eResource() == null ? null : model.eResource().getEObject(fragment);
		if (element != null && viewer != null) {
			viewer.setSelection(new StructuredSelection(element), true);
		}
	}

	/** How an element reads in the tree. */
	public static String label(Object element) {
		if (element instanceof Model root) {
			return "Model " + root.getName() + "  (" + root.getVariables().size() + " variables)";
		}
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
		refreshSheets();
		firePropertyChange(PROP_DIRTY);
		updateUndoRedo();
		if (viewer != null && !viewer.getControl().isDisposed()) {
			updateActions();
		}
	}

	private void commitPendingEdits() {
		for (TabbedPropertySheetPage sheet : sheets) {
			if (sheet.getControl() != null && !sheet.getControl().isDisposed() && sheet.getCurrentTab() != null) {
				for (var section : sheet.getCurrentTab().getSections()) {
					if (section instanceof PendingEdit pending) {
						pending.commitPending();
					}
				}
			}
		}
	}

	private void refreshSheets() {
		sheets.removeIf(sheet -> sheet.getControl() != null && sheet.getControl().isDisposed());
		sheets.stream().filter(sheet -> sheet.getControl() != null && sheet.getCurrentTab() != null).forEach(TabbedPropertySheetPage::refresh);
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
			TabbedPropertySheetPage page = new TabbedPropertySheetPage(this);
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
		var sourceFolder = org.kse.ui.ModelFiles.sourceFolder(getFile());
		String key = sourceFolder == null ? "" : sourceFolder.getFullPath().toString();
		if (catalog == null || !key.equals(catalogFolder)) {
			catalog = ModelFiles.catalog(getFile());
			catalogFolder = key;
		}
		return catalog;
	}

	@Override
	public String getContributorId() {
		return ID;
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
		commitPendingEdits();
		if (!java.util.Objects.equals(lastModified(file), seenOnDisk) && !org.eclipse.jface.dialogs.MessageDialog.openQuestion(getSite().getShell(), "File Changed",
				file.getFullPath() + " has been changed on disk since this editor read it. Overwrite that change with the editor's contents?")) {
			return;
		}
		saving = true;
		try {
			StatechartResources.save(model, Path.of(file.getLocationURI()));
			seenOnDisk = lastModified(file);
			for (var participant : saveParticipants) {
				participant.write();
			}
			((BasicCommandStack) domain.getCommandStack()).saveIsDone();
			// the folder, for the notation file written beside the model
			file.getParent().refreshLocal(IResource.DEPTH_ONE, monitor);
			firePropertyChange(PROP_DIRTY);
			updateActions();
		} catch (IOException | CoreException e) {
			org.eclipse.jface.dialogs.ErrorDialog.openError(getSite().getShell(), "Save", "Cannot save " + file.getFullPath(),
					org.eclipse.core.runtime.Status.error(e.getMessage(), e));
		} finally {
			saving = false;
		}
	}

	/** Reloads the saved file: unsaved edits are dropped, and so is the undo history. */
	public void doRevert() {
		IFile file = getFile();
		Model reloaded;
		try {
			var resourceSet = domain.getResourceSet();
			resourceSet.getResources().forEach(org.eclipse.emf.ecore.resource.Resource::unload);
			resourceSet.getResources().clear();
			seenOnDisk = lastModified(file);
			reloaded = StatechartResources.load(resourceSet, Path.of(file.getLocationURI()));
		} catch (IOException e) {
			org.eclipse.jface.dialogs.ErrorDialog.openError(getSite().getShell(), "Revert", "Cannot read " + file.getFullPath(),
					org.eclipse.core.runtime.Status.error(e.getMessage(), e));
			return;
		}
		model = reloaded;
		domain.getCommandStack().flush();
		((BasicCommandStack) domain.getCommandStack()).saveIsDone();
		if (viewer != null && !viewer.getControl().isDisposed()) {
			viewer.setInput(new Object[] { model });
			viewer.expandToLevel(4);
			viewer.setSelection(new StructuredSelection(model));
		}
		if (diagram != null) {
			// the diagram's session holds the model that was dropped: a new one takes the reloaded model
			saveParticipants.clear();
			diagram.reload();
		}
		refreshSheets();
		firePropertyChange(PROP_DIRTY);
		updateUndoRedo();
		updateActions();
	}

	/**
	 * The file changed on disk (say, the formula was transformed again): reloaded when the editor
	 * has no unsaved edits, otherwise the user chooses between the file and the edits.
	 */
	private void fileChanged(IResourceChangeEvent event) {
		IFile file = getFile();
		IResourceDelta delta = event.getDelta() == null || file == null ? null : event.getDelta().findMember(file.getFullPath());
		if (delta == null || saving) {
			return;
		}
		boolean removed = delta.getKind() == IResourceDelta.REMOVED && (delta.getFlags() & IResourceDelta.MOVED_TO) == 0;
		boolean changed = delta.getKind() == IResourceDelta.CHANGED && (delta.getFlags() & (IResourceDelta.CONTENT | IResourceDelta.REPLACED)) != 0;
		if (!removed && !changed) {
			return;
		}
		getSite().getShell().getDisplay().asyncExec(() -> {
			if (viewer == null || viewer.getControl().isDisposed() || saving) {
				return;
			}
			if (removed) {
				getSite().getPage().closeEditor(this, false);
			} else if (!isDirty()) {
				doRevert();
			} else if (!java.util.Objects.equals(lastModified(file), seenOnDisk)) {
				askAboutChangeOnDisk(file);
			}
		});
	}

	private void askAboutChangeOnDisk(IFile file) {
		FileTime changed = lastModified(file);
		int choice = new org.eclipse.jface.dialogs.MessageDialog(getSite().getShell(), "File Changed", null,
				file.getFullPath() + " has been changed on disk by another program, and this editor has unsaved edits.\n\n"
						+ "Reload drops the edits and shows the file; Keep My Edits keeps them (saving them then replaces the change on disk).",
				org.eclipse.jface.dialogs.MessageDialog.QUESTION, 0, "Reload", "Keep My Edits").open();
		if (choice == 0) {
			doRevert();
		} else {
			seenOnDisk = changed; // seen and set aside: a save may overwrite it without asking again
		}
	}

	/** When the file was last written on disk; null when it cannot be read. */
	private static FileTime lastModified(IFile file) {
		try {
			return java.nio.file.Files.getLastModifiedTime(Path.of(file.getLocationURI()));
		} catch (IOException | RuntimeException e) {
			return null;
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
		if (isDiagramShown() && diagram.isAvailable()) {
			diagram.getBrowser().setFocus();
		} else {
			viewer.getControl().setFocus();
		}
	}

	@Override
	public void dispose() {
		if (getFile() != null) {
			org.kse.ui.statechart.diagram.WorkspaceDiagramServer.unregister(Path.of(getFile().getLocationURI()), diagramHost);
		}
		ResourcesPlugin.getWorkspace().removeResourceChangeListener(fileListener);
		domain.getCommandStack().removeCommandStackListener(stackListener);
		adapterFactory.dispose();
		super.dispose();
	}
}
