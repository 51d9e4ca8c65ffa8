/*
 * Hand-written; created once from the Xtext template.
 */
package org.kse.expression.ide;

import com.google.inject.Guice;
import com.google.inject.Injector;
import org.eclipse.xtext.util.Modules2;
import org.kse.expression.TransitionExpressionRuntimeModule;
import org.kse.expression.TransitionExpressionStandaloneSetup;

/**
 * Initialization support for running Xtext languages as language servers.
 */
public class TransitionExpressionIdeSetup extends TransitionExpressionStandaloneSetup {

	@Override
	public Injector createInjector() {
		return Guice.createInjector(Modules2.mixin(new TransitionExpressionRuntimeModule(), new TransitionExpressionIdeModule()));
	}
	
}
