package org.kse.liveness;

import java.util.List;

import org.eclipse.emf.common.util.URI;
import org.eclipse.xtext.diagnostics.Severity;
import org.eclipse.xtext.validation.Issue;
import org.kse.liveness.liveness.FormulaFile;
import org.kse.xtext.support.TextParsing;

import com.google.inject.Injector;

/**
 * Parses and validates formula text outside any editor. Every problem comes back as
 * an {@link Issue} with line and column; nothing the text contains makes it throw.
 */
public final class FormulaLoader {

	/** A parsed formula file and everything wrong with it. */
	public record Result(FormulaFile file, List<Issue> issues) {
		public boolean hasErrors() {
			return issues.stream().anyMatch(issue -> issue.getSeverity() == Severity.ERROR);
		}
	}

	private static final class Holder {
		static final Injector INJECTOR = new LivenessStandaloneSetup().createInjectorAndDoEMFRegistration();
	}

	public static Injector injector() {
		return Holder.INJECTOR;
	}

	private FormulaLoader() {
	}

	/** Parses {@code text} as if read from {@code uri} (the URI only names it in messages). */
	public static Result load(String text, URI uri) {
		URI named = uri.fileExtension() == null || !List.of("liveness", "txt").contains(uri.fileExtension()) ? uri.appendFileExtension("liveness") : uri;
		TextParsing.Parsed parsed = TextParsing.parse(injector(), named, text, "brackets nested too deeply");
		return new Result((FormulaFile) parsed.root(), parsed.issues());
	}
}
