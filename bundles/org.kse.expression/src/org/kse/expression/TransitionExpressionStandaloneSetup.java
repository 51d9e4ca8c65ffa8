/*
 * Hand-written; started from the Xtext template.
 */
package org.kse.expression;


/**
 * Initialization support for running Xtext languages without Equinox extension registry.
 */
public class TransitionExpressionStandaloneSetup extends TransitionExpressionStandaloneSetupGenerated {

	public static void doSetup() {
		new TransitionExpressionStandaloneSetup().createInjectorAndDoEMFRegistration();
	}
}
