/*
 * Hand-written; created once from the Xtext template.
 */
package org.kse.proto;


/**
 * Initialization support for running Xtext languages without Equinox extension registry.
 */
public class ProtoStandaloneSetup extends ProtoStandaloneSetupGenerated {

	public static void doSetup() {
		new ProtoStandaloneSetup().createInjectorAndDoEMFRegistration();
	}
}
