package org.kse.ui.messages;

import java.nio.file.Path;
import java.util.Optional;

import org.eclipse.core.filesystem.EFS;
import org.eclipse.core.resources.IFile;
import org.eclipse.core.resources.IResource;
import org.eclipse.core.resources.IResourceChangeEvent;
import org.eclipse.core.resources.IResourceChangeListener;
import org.eclipse.core.resources.IResourceDelta;
import org.eclipse.core.resources.ResourcesPlugin;
import org.eclipse.core.runtime.CoreException;
import org.eclipse.core.runtime.ILog;
import org.eclipse.core.runtime.IPath;
import org.eclipse.core.runtime.IProgressMonitor;
import org.eclipse.core.runtime.Status;
import org.eclipse.core.runtime.jobs.Job;
import org.eclipse.jface.text.IDocument;
import org.eclipse.jface.text.IDocumentExtension3;
import org.eclipse.jface.text.ITextSelection;
import org.eclipse.jface.text.rules.FastPartitioner;
import org.eclipse.ui.IEditorPart;
import org.eclipse.ui.IEditorInput;
import org.eclipse.ui.IEditorSite;
import org.eclipse.ui.IWorkbenchPage;
import org.eclipse.ui.PartInitException;
import org.eclipse.ui.editors.text.TextEditor;
import org.eclipse.ui.ide.IDE;
import org.eclipse.ui.views.contentoutline.IContentOutlinePage;
import org.kse.messages.Field;
import org.kse.messages.ProtoFile;
import org.kse.messages.ProtoReader;

/**
 * The text editor of {@code .proto} message files: colours, problems while typing (the file's own
 * and those of linking it with its folder and the standard messages), an outline, and go to the
 * declaration of a field's type (F3, Ctrl+click), also into another file of the folder or a
 * standard file (opened read-only). JFace text with the reader of {@code org.kse.messages}, as
 * the formula editor is built (ADR 0009, 0019).
 */
public class ProtoEditor extends TextEditor {

	public static final String ID = "org.kse.ui.messages.editor";

	private final ProtoChecker checker = new ProtoChecker(this);
	private ProtoOutline outline;
	/** Checks again when another .proto file changes on disk: its types are this file's too. */
	private final IResourceChangeListener neighbours = this::resourcesChanged;
	private final Job recheck = Job.create("Checking messages", (IProgressMonitor monitor) -> {
		checker.check();
		return Status.OK_STATUS;
	});

	@Override
	protected void initializeEditor() {
		super.initializeEditor();
		setSourceViewerConfiguration(new ProtoViewerConfiguration(this, getPreferenceStore()));
	}

	@Override
	public void init(IEditorSite site, IEditorInput input) throws PartInitException {
		// not in initializeEditor: the superclass' constructor calls it before this class' fields exist
		super.init(site, input);
		recheck.setSystem(true);
		ResourcesPlugin.getWorkspace().addResourceChangeListener(neighbours, IResourceChangeEvent.POST_CHANGE);
	}

	@Override
	protected void initializeKeyBindingScopes() {
		setKeyBindingScopes(new String[] { "org.kse.ui.messages.editorScope" });
	}

	@Override
	protected void doSetInput(IEditorInput input) throws CoreException {
		super.doSetInput(input);
		IDocument document = getDocumentProvider() == null ? null : getDocumentProvider().getDocument(input);
		// The document may be shared with another editor of the same file: partition it once.
		if (document instanceof IDocumentExtension3 extension && extension.getDocumentPartitioner(ProtoScanner.PARTITIONING) == null) {
			FastPartitioner partitioner = new FastPartitioner(ProtoScanner.partitions(), ProtoScanner.PARTITIONS);
			extension.setDocumentPartitioner(ProtoScanner.PARTITIONING, partitioner);
			partitioner.connect(document);
		}
	}

	@Override
	public void dispose() {
		ResourcesPlugin.getWorkspace().removeResourceChangeListener(neighbours);
		recheck.cancel();
		super.dispose();
	}

	ProtoChecker checker() {
		return checker;
	}

	/** How long the last check of the text took, in nanoseconds (read, linked, markers made). */
	public long lastCheckNanos() {
		return checker.lastCheckNanos;
	}

	@Override
	public <T> T getAdapter(Class<T> adapter) {
		if (adapter == IContentOutlinePage.class) {
			if (outline == null || outline.getControl() != null && outline.getControl().isDisposed()) {
				outline = new ProtoOutline(this);
			}
			return adapter.cast(outline);
		}
		return super.getAdapter(adapter);
	}

	/** Called after each check of the text (any thread): the outline follows the text. */
	void textChecked(ProtoFile checked) {
		if (outline != null && getSite() != null) {
			getSite().getShell().getDisplay().asyncExec(() -> {
				if (outline != null) {
					outline.update(checked);
				}
			});
		}
	}

	private void resourcesChanged(IResourceChangeEvent event) {
		IFile file = getFile();
		if (file == null || event.getDelta() == null) {
			return;
		}
		IPath folder = file.getParent().getFullPath();
		boolean[] changed = new boolean[1];
		try {
			event.getDelta().accept(delta -> {
				IResource resource = delta.getResource();
				if (resource.getType() == IResource.FILE) {
					changed[0] |= "proto".equals(resource.getFileExtension()) && !resource.equals(file)
							&& folder.isPrefixOf(resource.getFullPath()) && (delta.getKind() != IResourceDelta.CHANGED
									|| (delta.getFlags() & (IResourceDelta.CONTENT | IResourceDelta.REPLACED)) != 0);
					return false;
				}
				return !changed[0] && (resource.getFullPath().isPrefixOf(folder) || folder.isPrefixOf(resource.getFullPath()));
			});
		} catch (CoreException e) {
			ILog.of(ProtoEditor.class).log(e.getStatus());
		}
		if (changed[0]) {
			// markers cannot be made while the workspace tells of a change: a job does it, after the same pause as typing
			recheck.schedule(ProtoViewerConfiguration.CHECK_DELAY);
		}
	}

	/** The workspace file being edited, or null for a standard file or a file outside the workspace. */
	public IFile getFile() {
		return getEditorInput() == null ? null : getEditorInput().getAdapter(IFile.class);
	}

	/** The text as it is in the editor now, saved or not. */
	public String getText() {
		return getDocumentProvider().getDocument(getEditorInput()).get();
	}

	ProtoFile parse(String text) {
		IFile file = getFile();
		return ProtoReader.read(Path.of(file == null ? getEditorInput().getName() : file.getName()), text);
	}

	/** A field's type name at an offset: where it is written and where it is declared. */
	record TypeAt(Field field, int start, int end, Optional<LinkedProto.Declaration> declaration) {
	}

	/** The field type name at {@code offset} of {@code text}, linked; null when there is none. */
	TypeAt typeAt(String text, int offset) {
		LinkedProto linked = link(text);
		if (linked == null) {
			return null;
		}
		Optional<Field> field = linked.fieldWithTypeAt(offset);
		if (field.isEmpty()) {
			return null;
		}
		int start = linked.positions().offset(field.get().typeLine(), field.get().typeColumn());
		return new TypeAt(field.get(), start, linked.positions().qualifiedNameEnd(start), linked.declarationOf(field.get()));
	}

	/** This editor's text linked as the checker links it; a standard file with the other standard files. */
	private LinkedProto link(String text) {
		if (getEditorInput() instanceof StandardFileInput standard) {
			return LinkedProto.standard(standard.fileName());
		}
		Path location = ProtoChecker.locationOf(getFile());
		return location == null ? null : LinkedProto.of(location, text);
	}

	/** Go to the declaration of the type at the cursor (F3); false, with a word on the status line, when there is none. */
	public boolean openDeclarationAtCursor() {
		int offset = ((ITextSelection) getSelectionProvider().getSelection()).getOffset();
		TypeAt at = typeAt(getText(), offset);
		if (at == null) {
			status("Open Declaration: put the cursor on the type of a field (a message or enum name)");
			return false;
		}
		if (at.declaration().isEmpty()) {
			status(at.field().scalarKind().isPresent() ? at.field().typeName() + " is a scalar type of protobuf"
					: "No file of this folder or of the standard messages declares " + at.field().typeName());
			return false;
		}
		return open(at.declaration().get());
	}

	/**
	 * Shows a declaration: here, in the editor of another file of the folder, or in a standard
	 * file opened read-only; the name is selected.
	 */
	boolean open(LinkedProto.Declaration declaration) {
		IWorkbenchPage page = getSite().getPage();
		try {
			IEditorPart part;
			if (declaration.standardName() != null) {
				part = IDE.openEditor(page, new StandardFileInput(declaration.standardName()), ID);
			} else if (declaration.location() == null) {
				return false;
			} else if (declaration.location().equals(ProtoChecker.locationOf(getFile()))) {
				part = this;
			} else {
				part = openFile(page, declaration.location());
			}
			if (part instanceof ProtoEditor target) {
				LinkedProto.Positions positions = new LinkedProto.Positions(target.getText());
				target.selectAndReveal(positions.offset(declaration.type().line(), declaration.type().column()),
						declaration.type().name().length());
				if (declaration.standardName() != null) {
					target.status(declaration.type().fullName() + " is a standard message type of KSE, declared in "
							+ new StandardFileInput(declaration.standardName()).importPath() + " (read-only)");
				}
			}
			return true;
		} catch (PartInitException e) {
			ILog.of(ProtoEditor.class).error("cannot open the declaration of " + declaration.type().fullName(), e);
			status("Cannot open " + declaration.type().fullName() + ": " + e.getMessage());
			return false;
		}
	}

	/** Another file of the folder: as a workspace file when it is one (refreshed when new on disk). */
	private static IEditorPart openFile(IWorkbenchPage page, Path location) throws PartInitException {
		IFile file = ResourcesPlugin.getWorkspace().getRoot().getFileForLocation(IPath.fromPath(location));
		if (file != null && !file.exists()) {
			try {
				file.getParent().refreshLocal(IResource.DEPTH_ONE, null);
			} catch (CoreException e) {
				ILog.of(ProtoEditor.class).log(e.getStatus());
			}
		}
		if (file != null && file.exists()) {
			return IDE.openEditor(page, file, ID);
		}
		return IDE.openEditorOnFileStore(page, EFS.getLocalFileSystem().getStore(location.toUri()));
	}

	private volatile String statusMessage = "";

	private void status(String message) {
		statusMessage = message;
		getEditorSite().getActionBars().getStatusLineManager().setMessage(message);
	}

	/** What the editor last said on the status line (the UI tests read it: a status line has no getter). */
	public String statusMessage() {
		return statusMessage;
	}
}
