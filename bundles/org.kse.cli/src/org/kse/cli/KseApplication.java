package org.kse.cli;

import org.eclipse.equinox.app.IApplication;
import org.eclipse.equinox.app.IApplicationContext;

/** The headless {@code kse} command as an Equinox application of the KSE product. */
public class KseApplication implements IApplication {

	@Override
	public Object start(IApplicationContext context) {
		String[] args = (String[]) context.getArguments().getOrDefault(IApplicationContext.APPLICATION_ARGS, new String[0]);
		int code = new Kse(System.out, System.err).run(args);
		System.out.flush();
		System.err.flush();
		return code;
	}

	@Override
	public void stop() {
		// runs to completion; nothing to interrupt
	}
}
