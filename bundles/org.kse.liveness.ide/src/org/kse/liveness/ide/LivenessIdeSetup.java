/*
 * Hand-written; created once from the Xtext template.
 */
package org.kse.liveness.ide;

import com.google.inject.Guice;
import com.google.inject.Injector;
import org.eclipse.xtext.util.Modules2;
import org.kse.liveness.LivenessRuntimeModule;
import org.kse.liveness.LivenessStandaloneSetup;

/**
 * Initialization support for running Xtext languages as language servers.
 */
public class LivenessIdeSetup extends LivenessStandaloneSetup {

	@Override
	public Injector createInjector() {
		return Guice.createInjector(Modules2.mixin(new LivenessRuntimeModule(), new LivenessIdeModule()));
	}
	
}
