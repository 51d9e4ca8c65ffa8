package org.kse.diagram.server;

import java.nio.file.Path;

import org.eclipse.glsp.server.di.ServerModule;
import org.eclipse.glsp.server.protocol.GLSPServer;

/**
 * GLSP's server module for the statechart diagram of one served folder, with KSE's
 * {@link StatechartGLSPServer}: whatever a client sends, no stack trace on the terminal.
 */
public class StatechartServerModule extends ServerModule {

	/** Serves the statecharts of a folder, as {@code sources} hands them out. */
	public StatechartServerModule(Path servedFolder, StatechartSources sources) {
		configureDiagramModule(new StatechartDiagramModule(servedFolder, sources));
	}

	@Override
	protected Class<? extends GLSPServer> bindGLSPServer() {
		return StatechartGLSPServer.class;
	}
}
