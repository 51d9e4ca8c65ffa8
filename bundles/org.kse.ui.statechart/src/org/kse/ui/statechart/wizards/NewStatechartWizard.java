package org.kse.ui.statechart.wizards;

import java.io.ByteArrayInputStream;
import java.io.IOException;
import java.io.InputStream;

import org.eclipse.core.resources.IFile;
import org.eclipse.jface.viewers.IStructuredSelection;
import org.eclipse.jface.wizard.Wizard;
import org.eclipse.ui.INewWizard;
import org.eclipse.ui.IWorkbench;
import org.eclipse.ui.dialogs.WizardNewFileCreationPage;
import org.eclipse.ui.wizards.newresource.BasicNewResourceWizard;
import org.kse.model.NodeKind;
import org.kse.model.StatechartResources;
import org.kse.model.statechart.Model;
import org.kse.model.statechart.Node;
import org.kse.model.statechart.StatechartFactory;
import org.kse.model.statechart.Transition;

/** New statechart with nothing but its root: an OR state whose START leads to its END. */
public class NewStatechartWizard extends Wizard implements INewWizard {

	private IWorkbench workbench;
	private IStructuredSelection selection;
	private WizardNewFileCreationPage page;

	@Override
	public void init(IWorkbench workbench, IStructuredSelection selection) {
		this.workbench = workbench;
		this.selection = selection;
		setWindowTitle("New Statechart");
	}

	/** The smallest valid statechart called {@code name}. */
	public static Model empty(String name) {
		StatechartFactory factory = StatechartFactory.eINSTANCE;
		Model model = factory.createModel();
		model.setName(name);
		Node root = factory.createNode();
		root.setName(Character.toLowerCase(name.charAt(0)) + name.substring(1));
		root.setLabel("0");
		root.setType(NodeKind.OR.name());
		Node start = factory.createNode();
		start.setName("0.1");
		start.setLabel("0.1");
		start.setType(NodeKind.START.name());
		Node end = factory.createNode();
		end.setName("0.2");
		end.setLabel("0.2");
		end.setType(NodeKind.END.name());
		root.getChildren().add(start);
		root.getChildren().add(end);
		model.getNodes().add(root);
		Transition transition = factory.createTransition();
		transition.setName("0.1_TO_0.2");
		transition.setSource(start);
		transition.setTarget(end);
		model.getTransitions().add(transition);
		return model;
	}

	@Override
	public void addPages() {
		page = new WizardNewFileCreationPage("statechart", selection) {
			@Override
			protected InputStream getInitialContents() {
				String name = getFileName().replaceFirst("\\\\.[^.]*$", "").replaceAll("[^A-Za-z0-9_]", "_");
				try {
					return new ByteArrayInputStream(StatechartResources.toBytes(empty(name.isEmpty() ? "Behaviour" : name)));
				} catch (IOException e) {
					throw new IllegalStateException(e);
				}
			}
		};
		page.setTitle("Statechart");
		page.setDescription("An empty statechart (.stct) to build by hand.");
		page.setFileExtension(StatechartResources.FILE_EXTENSION);
		page.setFileName("Behaviour.stct");
		addPage(page);
	}

	@Override
	public boolean performFinish() {
		IFile file = page.createNewFile();
		if (file != null) {
			BasicNewResourceWizard.selectAndReveal(file, workbench.getActiveWorkbenchWindow());
		}
		return file != null;
	}
}
