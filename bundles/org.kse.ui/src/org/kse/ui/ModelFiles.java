package org.kse.ui;

import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;

import org.eclipse.core.commands.ExecutionEvent;
import org.eclipse.core.resources.IContainer;
import org.eclipse.core.resources.IFile;
import org.eclipse.core.resources.IResource;
import org.eclipse.core.resources.ResourcesPlugin;
import org.eclipse.core.runtime.CoreException;
import org.eclipse.core.runtime.QualifiedName;
import org.eclipse.jface.viewers.ISelection;
import org.eclipse.jface.viewers.IStructuredSelection;
import org.eclipse.ui.IEditorPart;
import org.eclipse.ui.handlers.HandlerUtil;
import org.kse.model.StatechartResources;

/** The statechart files a command works on, and what KSE remembers about them. */
public final class ModelFiles {

	/** The source folder a model's code is generated into (workspace path), kept with the model. */
	public static final QualifiedName SOURCE_FOLDER = new QualifiedName("org.kse.ui", "sourceFolder");
	/** Whether the generated conditions log (the generator's logger variant). */
	public static final QualifiedName LOGGER = new QualifiedName("org.kse.ui", "logger");

	private ModelFiles() {
	}

	/** The .stct files selected in a view, or the one of the active editor. */
	public static List<IFile> of(ExecutionEvent event) {
		List<IFile> files = new ArrayList<>();
		ISelection selection = HandlerUtil.getCurrentSelection(event);
		if (selection instanceof IStructuredSelection structured) {
			for (Object element : structured) {
				IFile file = element instanceof IFile direct ? direct
						: element instanceof org.eclipse.core.runtime.IAdaptable adaptable ? adaptable.getAdapter(IFile.class) : null;
				if (isModel(file)) {
					files.add(file);
				}
			}
		}
		if (files.isEmpty()) {
			IEditorPart editor = HandlerUtil.getActiveEditor(event);
			IFile file = editor == null ? null : editor.getEditorInput().getAdapter(IFile.class);
			if (isModel(file)) {
				files.add(file);
			}
		}
		return files;
	}

	public static boolean isModel(IFile file) {
		return file != null && StatechartResources.FILE_EXTENSION.equals(file.getFileExtension());
	}

	public static Path location(IResource resource) {
		return Path.of(resource.getLocationURI());
	}

	/** The remembered source folder of a model, or null. */
	public static IContainer sourceFolder(IFile model) {
		try {
			String path = model.getPersistentProperty(SOURCE_FOLDER);
			if (path == null) {
				return null;
			}
			IResource folder = ResourcesPlugin.getWorkspace().getRoot().findMember(path);
			return folder instanceof IContainer container ? container : null;
		} catch (CoreException e) {
			return null;
		}
	}

	public static void remember(IFile model, IContainer folder, boolean logger) throws CoreException {
		model.setPersistentProperty(SOURCE_FOLDER, folder.getFullPath().toString());
		model.setPersistentProperty(LOGGER, Boolean.toString(logger));
	}

	/** The messages a model's expressions may use: the standard ones and those of its source folder's messages/. */
	public static org.kse.messages.MessageCatalog catalog(IFile model) {
		List<Path> folders = new ArrayList<>();
		IContainer sourceFolder = sourceFolder(model);
		if (sourceFolder != null) {
			folders.add(location(sourceFolder).resolve("messages"));
		}
		return org.kse.messages.StandardMessages.catalog(folders);
	}

	public static boolean logger(IFile model) {
		try {
			return Boolean.parseBoolean(model.getPersistentProperty(LOGGER));
		} catch (CoreException e) {
			return false;
		}
	}
}
