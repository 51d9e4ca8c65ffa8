package org.kse.ui.statechart;

import java.util.HashMap;
import java.util.Map;

import org.eclipse.core.resources.IFile;
import org.eclipse.core.resources.IMarker;
import org.eclipse.core.resources.IWorkspace;
import org.eclipse.core.runtime.CoreException;
import org.eclipse.emf.common.util.Diagnostic;
import org.eclipse.emf.ecore.EObject;
import org.eclipse.emf.ecore.util.EcoreUtil;
import org.kse.model.statechart.Model;
import org.kse.validation.ModelValidation;
import org.kse.ui.ModelFiles;

/** Validates a statechart and shows each diagnostic as a problem marker that names its element. */
public final class ModelMarkers {

	public static final String MARKER = "org.kse.ui.modelProblem";
	/** URI fragment of the model element a marker is about. */
	public static final String ELEMENT = "org.kse.ui.element";

	private ModelMarkers() {
	}

	/** Replaces the model's markers by its diagnostics; returns {errors, warnings}. */
	public static int[] validate(IFile file, Model model) throws CoreException {
		Diagnostic diagnostics = ModelValidation.validate(model, ModelFiles.catalog(file));
		int[] counts = new int[2];
		file.getWorkspace().run(monitor -> {
			file.deleteMarkers(MARKER, false, 0);
			for (Diagnostic diagnostic : diagnostics.getChildren()) {
				boolean error = diagnostic.getSeverity() == Diagnostic.ERROR;
				counts[error ? 0 : 1]++;
				// all attributes at once: a reader never sees a marker half made
				Map<String, Object> attributes = new HashMap<>();
				attributes.put(IMarker.MESSAGE, diagnostic.getMessage());
				attributes.put(IMarker.SEVERITY, error ? IMarker.SEVERITY_ERROR : IMarker.SEVERITY_WARNING);
				EObject element = null;
				for (Object data : diagnostic.getData()) {
					if (data instanceof EObject object) {
						element = object;
						break;
					}
				}
				if (element != null) {
					attributes.put(ELEMENT, EcoreUtil.getURI(element).fragment());
					attributes.put(IMarker.LOCATION, org.kse.validation.Labels.describe(element));
				}
				file.createMarker(MARKER, attributes);
			}
		}, file, IWorkspace.AVOID_UPDATE, null);
		return counts;
	}

	/** A marker on the file itself, for a model that cannot be read. */
	public static void unreadable(IFile file, String message) throws CoreException {
		file.deleteMarkers(MARKER, false, 0);
		file.createMarker(MARKER, Map.of(IMarker.MESSAGE, message, IMarker.SEVERITY, IMarker.SEVERITY_ERROR));
	}
}
