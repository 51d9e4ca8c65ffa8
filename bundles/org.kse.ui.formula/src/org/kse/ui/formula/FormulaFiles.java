package org.kse.ui.formula;

import java.util.List;

import org.eclipse.core.resources.IFile;
import org.eclipse.core.runtime.Path;

/** The formula file of a statechart: the one it was transformed from, in its folder under its name. */
final class FormulaFiles {

	private static final List<String> EXTENSIONS = List.of("liveness", "txt");

	private FormulaFiles() {
	}

	/** The {@code .liveness} (or the original tool's {@code .txt}) beside the model, or null. */
	static IFile existing(IFile model) {
		for (String extension : EXTENSIONS) {
			IFile formula = named(model, extension);
			if (formula.exists()) {
				return formula;
			}
		}
		return null;
	}

	/** The existing formula file, else the {@code .liveness} that would be made. */
	static IFile existingOrNew(IFile model) {
		IFile existing = existing(model);
		return existing != null ? existing : named(model, EXTENSIONS.get(0));
	}

	static String baseName(IFile model) {
		return model.getFullPath().removeFileExtension().lastSegment();
	}

	private static IFile named(IFile model, String extension) {
		return model.getParent().getFile(Path.fromPortableString(baseName(model) + "." + extension));
	}
}
