package org.kse.diagram.server;

import java.io.IOException;
import java.nio.file.Path;

import org.eclipse.emf.edit.domain.EditingDomain;
import org.kse.model.StatechartResources;
import org.kse.model.edit.StatechartEdits;
import org.kse.model.statechart.Model;

/** Statecharts read from their files, one copy per diagram session ({@code kse serve}). */
public final class FileSources implements StatechartSources {

	@Override
	public Source open(Path file) throws IOException {
		EditingDomain domain = StatechartEdits.newDomain();
		Model model = StatechartResources.load(domain.getResourceSet(), file);
		return new Source() {
			@Override
			public Model model() {
				return model;
			}

			@Override
			public EditingDomain domain() {
				return domain;
			}

			@Override
			public void save(NotationWriter notation) throws IOException {
				StatechartResources.save(model, file);
				notation.write();
			}
		};
	}
}
