/*
 * Hand-written; created once from the Xtext template.
 */
package org.kse.liveness;

import org.eclipse.xtext.parser.antlr.ISyntaxErrorMessageProvider;
import org.kse.liveness.validation.LivenessSyntaxErrorMessageProvider;

/**
 * Use this class to register components to be used at runtime / without the Equinox extension registry.
 */
public class LivenessRuntimeModule extends AbstractLivenessRuntimeModule {

	/** Syntax errors say what the formula lacks, not which token the parser wanted. */
	public Class<? extends ISyntaxErrorMessageProvider> bindISyntaxErrorMessageProvider() {
		return LivenessSyntaxErrorMessageProvider.class;
	}
}
