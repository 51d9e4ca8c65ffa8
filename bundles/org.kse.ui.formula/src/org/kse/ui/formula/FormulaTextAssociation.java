package org.kse.ui.formula;

import java.io.BufferedReader;
import java.io.IOException;
import java.io.InputStreamReader;
import java.nio.charset.StandardCharsets;
import java.util.regex.Pattern;

import org.eclipse.core.resources.IFile;
import org.eclipse.core.runtime.CoreException;
import org.eclipse.core.runtime.content.IContentType;
import org.eclipse.ui.IEditorDescriptor;
import org.eclipse.ui.IEditorInput;
import org.eclipse.ui.PlatformUI;
import org.eclipse.ui.ide.IEditorAssociationOverride;
import org.kse.ui.KseProject;

/**
 * The original tool kept formulas in {@code .txt} files, so a KSE project holds them too: there a
 * {@code .txt} whose text is formulas opens in the formula editor. Any other {@code .txt} (notes,
 * CMakeLists.txt), and every {@code .txt} outside KSE projects, keeps its usual editor, and the
 * editor chosen for a file with Open With stays the user's.
 */
public class FormulaTextAssociation implements IEditorAssociationOverride {

	/** The original tool's title line: the model's name alone. */
	private static final Pattern TITLE = Pattern.compile("[A-Za-z_][A-Za-z0-9_]*");
	private static final Pattern FORMULA = Pattern.compile("[A-Za-z_][A-Za-z0-9_]*[ \\t\\f\\u00A0]*=.*");
	/** Enough lines to get past a comment header; a formula file shows what it is at once. */
	private static final int LINES_READ = 50;

	@Override
	public IEditorDescriptor overrideDefaultEditor(IEditorInput input, IContentType contentType, IEditorDescriptor editor) {
		IFile file = input == null ? null : input.getAdapter(IFile.class);
		if (file == null || !"txt".equalsIgnoreCase(file.getFileExtension()) || chosenByTheUser(file) || !KseProject.is(file.getProject())
				|| !holdsFormulas(file)) {
			return editor;
		}
		IEditorDescriptor formulaEditor = PlatformUI.getWorkbench().getEditorRegistry().findEditor(FormulaEditor.ID);
		return formulaEditor == null ? editor : formulaEditor;
	}

	@Override
	public IEditorDescriptor overrideDefaultEditor(String fileName, IContentType contentType, IEditorDescriptor editor) {
		return editor; // a name alone does not say where the file is nor what it holds
	}

	@Override
	public IEditorDescriptor[] overrideEditors(IEditorInput input, IContentType contentType, IEditorDescriptor[] editors) {
		return editors;
	}

	@Override
	public IEditorDescriptor[] overrideEditors(String fileName, IContentType contentType, IEditorDescriptor[] editors) {
		return editors;
	}

	/** Open With remembers the editor chosen for the file; the workbench asks this override after it. */
	private static boolean chosenByTheUser(IFile file) {
		try {
			return file.getPersistentProperty(org.eclipse.ui.ide.IDE.EDITOR_KEY) != null;
		} catch (CoreException e) {
			return false;
		}
	}

	/**
	 * Whether the file's first line that is neither blank nor a comment is a formula
	 * ({@code name = ...}), or the original's title line followed by a formula.
	 */
	static boolean holdsFormulas(IFile file) {
		try (BufferedReader reader = new BufferedReader(new InputStreamReader(file.getContents(true), charset(file)))) {
			boolean titled = false;
			String line;
			for (int read = 0; read < LINES_READ && (line = reader.readLine()) != null; read++) {
				String text = line.strip();
				if (text.isEmpty() || text.startsWith("//")) {
					continue;
				}
				if (FORMULA.matcher(text).matches()) {
					return true;
				}
				if (titled || !TITLE.matcher(text).matches()) {
					return false;
				}
				titled = true;
			}
			return false;
		} catch (CoreException | IOException e) {
			return false; // unreadable here: the usual editor says why
		}
	}

	private static java.nio.charset.Charset charset(IFile file) {
		try {
			return java.nio.charset.Charset.forName(file.getCharset());
		} catch (CoreException | IllegalArgumentException e) {
			return StandardCharsets.UTF_8;
		}
	}
}
