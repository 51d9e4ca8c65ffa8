package org.kse.liveness;

/**
 * Initialization support for running Xtext languages without Equinox extension registry.
 */
public class LivenessStandaloneSetup extends LivenessStandaloneSetupGenerated {

	public static void doSetup() {
		new LivenessStandaloneSetup().createInjectorAndDoEMFRegistration();
	}
}
