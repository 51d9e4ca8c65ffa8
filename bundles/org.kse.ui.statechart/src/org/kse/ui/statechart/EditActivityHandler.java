package org.kse.ui.statechart;

import java.io.IOException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;

import org.eclipse.core.commands.AbstractHandler;
import org.eclipse.core.commands.ExecutionEvent;
import org.eclipse.core.commands.ExecutionException;
import org.eclipse.core.resources.IContainer;
import org.eclipse.core.resources.IFile;
import org.eclipse.jface.dialogs.MessageDialog;
import org.eclipse.jface.viewers.LabelProvider;
import org.eclipse.jface.window.Window;
import org.eclipse.swt.widgets.Shell;
import org.eclipse.ui.IWorkbenchPage;
import org.eclipse.ui.PartInitException;
import org.eclipse.ui.dialogs.ElementListSelectionDialog;
import org.eclipse.ui.handlers.HandlerUtil;
import org.eclipse.ui.ide.IDE;
import org.kse.generator.monas.GenerationPlan;
import org.kse.model.StatechartResources;
import org.kse.ui.preferences.KsePreferences;
import org.kse.ui.ModelFiles;

/**
 * "Edit Activity": opens the C++ of one of the model's activities (BASIC states) from its
 * source folder, in the internal editor or the external command of the KSE preferences.
 */
public class EditActivityHandler extends AbstractHandler {

	@Override
	public Object execute(ExecutionEvent event) throws ExecutionException {
		List<IFile> files = ModelFiles.of(event);
		Shell shell = HandlerUtil.getActiveShellChecked(event);
		if (files.size() != 1) {
			return null;
		}
		IFile model = files.get(0);
		IContainer folder = ModelFiles.sourceFolder(model);
		if (folder == null) {
			MessageDialog.openInformation(shell, "Edit Activity", model.getName() + " is not connected to a source folder yet: generate its code first.");
			return null;
		}
		String activity = selectedActivity(event);
		if (activity == null) {
			activity = chooseActivity(shell, model);
			if (activity == null) {
				return null;
			}
		}
		IFile source = folder.getFile(org.eclipse.core.runtime.Path.fromPortableString("activities/" + activity + "/" + activity + ".cpp"));
		if (!source.exists()) {
			MessageDialog.openInformation(shell, "Edit Activity", source.getFullPath() + " does not exist yet: generate the code of " + model.getName() + " first.");
			return null;
		}
		open(HandlerUtil.getActiveWorkbenchWindowChecked(event).getActivePage(), source);
		return null;
	}

	/** Opens an activity's source as the preferences say. */
	public static void open(IWorkbenchPage page, IFile source) throws ExecutionException {
		if (KsePreferences.externalActivityEditor()) {
			List<String> command = KsePreferences.command(KsePreferences.node().get(KsePreferences.ACTIVITY_EDITOR_COMMAND, ""),
					Map.of("file", Path.of(source.getLocationURI()).toString()));
			try {
				new ProcessBuilder(command).inheritIO().start();
			} catch (IOException e) {
				throw new ExecutionException("cannot start the activity editor " + command + ": " + e.getMessage(), e);
			}
			return;
		}
		try {
			IDE.openEditor(page, source);
		} catch (PartInitException e) {
			throw new ExecutionException("cannot open " + source.getFullPath() + ": " + e.getMessage(), e);
		}
	}

	/** The activity of the BASIC state selected in the statechart editor, as the original tool's Edit Activity took it. */
	private static String selectedActivity(ExecutionEvent event) {
		if (HandlerUtil.getCurrentSelection(event) instanceof org.eclipse.jface.viewers.IStructuredSelection selection
				&& selection.getFirstElement() instanceof org.kse.model.statechart.Node node && org.kse.model.NodeKind.BASIC.is(node)
				&& node.eResource() != null) {
			org.kse.model.statechart.Model owner = (org.kse.model.statechart.Model) org.eclipse.emf.ecore.util.EcoreUtil.getRootContainer(node);
			return GenerationPlan.of(owner).activityName(node);
		}
		return null;
	}

	private static String chooseActivity(Shell shell, IFile model) throws ExecutionException {
		List<String> activities;
		try {
			activities = new ArrayList<>(GenerationPlan.of(StatechartResources.load(ModelFiles.location(model))).activities().keySet());
		} catch (IOException e) {
			throw new ExecutionException("cannot read " + model.getFullPath() + ": " + e.getMessage(), e);
		}
		ElementListSelectionDialog dialog = new ElementListSelectionDialog(shell, new LabelProvider());
		dialog.setTitle("Edit Activity");
		dialog.setMessage("The activity of " + model.getName() + " to edit:");
		dialog.setElements(activities.toArray());
		dialog.setMultipleSelection(false);
		return dialog.open() == Window.OK ? (String) dialog.getFirstResult() : null;
	}
}
