package org.kse.ui.formula.tests;

import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.ByteArrayInputStream;
import java.nio.charset.StandardCharsets;
import java.util.ArrayList;
import java.util.Collections;
import java.util.List;

import org.eclipse.core.resources.IFile;
import org.eclipse.core.resources.IMarker;
import org.eclipse.core.resources.IProject;
import org.eclipse.core.resources.IResource;
import org.eclipse.core.resources.ResourcesPlugin;
import org.eclipse.core.runtime.CoreException;
import org.eclipse.emf.common.util.URI;
import org.eclipse.jface.text.IDocument;
import org.eclipse.ui.PlatformUI;
import org.eclipse.ui.ide.IDE;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.extension.ExtendWith;
import org.kse.liveness.FormulaLoader;
import org.kse.ui.formula.FormulaEditor;
import org.kse.testing.ui.Ui;
import org.kse.testing.ui.UnexpectedDialogs;

/**
 * Benchmark (prints figures, asserts only that markers come and go): in a 500-line formula
 * file, the time from an edit that breaks a formula to its error marker, and from the fix to the
 * marker's removal; the baseline is parsing and checking the same text alone, in the same run.
 */
@ExtendWith(UnexpectedDialogs.class)
class KeystrokeToMarkerBenchmarkTest {

	private static final int LINES = 500;
	private static final int ROUNDS = 15;

	@Test
	void keystrokeToMarkerOnA500LineFormula() throws Exception {
		StringBuilder text = new StringBuilder();
		for (int i = 0; i < LINES - 1; i++) {
			text.append("c").append(i).append(" = A").append(i).append(".c").append(i + 1).append('\n');
		}
		text.append("c").append(LINES - 1).append(" = A").append(LINES - 1).append('\n');
		IProject project = ResourcesPlugin.getWorkspace().getRoot().getProject("Bench");
		if (!project.exists()) {
			project.create(null);
		}
		project.open(null);
		IFile file = project.getFile("Big.liveness");
		file.create(new ByteArrayInputStream(text.toString().getBytes(StandardCharsets.UTF_8)), true, null);
		FormulaEditor editor = (FormulaEditor) IDE.openEditor(PlatformUI.getWorkbench().getActiveWorkbenchWindow().getActivePage(), file,
				FormulaEditor.ID);
		IDocument document = editor.getDocumentProvider().getDocument(editor.getEditorInput());
		assertTrue(Ui.waitUntil(() -> errors(file) == 0, 10_000));
		Ui.settle(1000);

		int at = document.getLineOffset(LINES / 2) + document.getLineLength(LINES / 2) - 1;
		List<Long> toMarker = new ArrayList<>();
		List<Long> toClear = new ArrayList<>();
		for (int round = 0; round < ROUNDS; round++) {
			long start = System.nanoTime();
			document.replace(at, 0, " |");
			assertTrue(Ui.waitUntil(() -> errors(file) > 0, 10_000), "the marker comes");
			toMarker.add((System.nanoTime() - start) / 1_000_000);
			start = System.nanoTime();
			document.replace(at, 2, "");
			assertTrue(Ui.waitUntil(() -> errors(file) == 0, 10_000), "and goes");
			toClear.add((System.nanoTime() - start) / 1_000_000);
		}
		List<Long> check = new ArrayList<>();
		for (int round = 0; round < ROUNDS; round++) {
			long start = System.nanoTime();
			FormulaLoader.load(document.get(), URI.createURI("bench.liveness"));
			check.add((System.nanoTime() - start) / 1_000_000);
		}
		System.out.printf("[ benchmark ] keystroke to error marker, %d-line formula: median %d ms, p95 %d ms; fix to no marker: median %d ms, "
				+ "p95 %d ms (the editor waits 250 ms of quiet typing); parse and check alone: median %d ms; ratio %.1f%n", LINES, median(toMarker),
				p95(toMarker), median(toClear), p95(toClear), median(check), (double) median(toMarker) / Math.max(1, median(check)));
		editor.close(false);
	}

	private static int errors(IFile file) {
		try {
			int count = 0;
			for (IMarker marker : file.findMarkers("org.kse.ui.formulaProblem", false, IResource.DEPTH_ZERO)) {
				count += marker.getAttribute(IMarker.SEVERITY, -1) == IMarker.SEVERITY_ERROR ? 1 : 0;
			}
			return count;
		} catch (CoreException e) {
			return -1;
		}
	}

	private static long median(List<Long> values) {
		List<Long> sorted = new ArrayList<>(values);
		Collections.sort(sorted);
		return sorted.get(sorted.size() / 2);
	}

	private static long p95(List<Long> values) {
		List<Long> sorted = new ArrayList<>(values);
		Collections.sort(sorted);
		return sorted.get((int) Math.ceil(0.95 * sorted.size()) - 1);
	}
}
