package org.kse.transform;

import java.util.List;
import java.util.concurrent.atomic.AtomicReference;

import org.eclipse.emf.common.util.URI;
import org.eclipse.xtext.validation.Issue;
import org.kse.liveness.FormulaLoader;
import org.kse.model.statechart.Model;

/**
 * Formula text in, statechart out: parse, validate, and transform only when the
 * formulas have no error.
 */
public final class FormulaTransformation {

	/** The model (null when the formulas have errors) and every issue of the formulas. */
	public record Outcome(Model model, List<Issue> issues) {
	}

	/** Deeply nested capabilities recurse deeply; give the transformation room. */
	private static final long STACK_SIZE = 512L * 1024 * 1024;

	private FormulaTransformation() {
	}

	/**
	 * @param text      the formula file's content
	 * @param uri       where the text comes from (named in messages)
	 * @param modelName the model's name, or null to take the file's title line or else the root's name
	 */
	public static Outcome run(String text, URI uri, String modelName) {
		FormulaLoader.Result formulas = FormulaLoader.load(text, uri);
		if (formulas.hasErrors() || formulas.file() == null) {
			return new Outcome(null, formulas.issues());
		}
		return new Outcome(transform(formulas, modelName), formulas.issues());
	}

	private static Model transform(FormulaLoader.Result formulas, String modelName) {
		AtomicReference<Model> model = new AtomicReference<>();
		AtomicReference<Throwable> failure = new AtomicReference<>();
		Thread worker = new Thread(null, () -> {
			try {
				model.set(new FormulaToStatechart().transform(formulas.file(), modelName));
			} catch (Throwable e) {
				failure.set(e);
			}
		}, "kse-transform", STACK_SIZE);
		worker.start();
		try {
			worker.join();
		} catch (InterruptedException e) {
			Thread.currentThread().interrupt();
			throw new IllegalStateException("interrupted while transforming", e);
		}
		if (failure.get() != null) {
			throw new IllegalStateException("the transformation failed: " + failure.get(), failure.get());
		}
		return model.get();
	}
}
