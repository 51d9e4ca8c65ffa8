/*
 * Hand-written; created once from the Xtext template.
 */
package org.kse.proto.ide;

import com.google.inject.Guice;
import com.google.inject.Injector;
import org.eclipse.xtext.util.Modules2;
import org.kse.proto.ProtoRuntimeModule;
import org.kse.proto.ProtoStandaloneSetup;

/**
 * Initialization support for running Xtext languages as language servers.
 */
public class ProtoIdeSetup extends ProtoStandaloneSetup {

	@Override
	public Injector createInjector() {
		return Guice.createInjector(Modules2.mixin(new ProtoRuntimeModule(), new ProtoIdeModule()));
	}
	
}
