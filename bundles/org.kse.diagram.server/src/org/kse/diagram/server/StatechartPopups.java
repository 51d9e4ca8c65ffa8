package org.kse.diagram.server;

import java.util.Optional;

import org.eclipse.emf.ecore.EObject;
import org.eclipse.glsp.graph.GHtmlRoot;
import org.eclipse.glsp.graph.GModelElement;
import org.eclipse.glsp.graph.builder.impl.GHtmlRootBuilder;
import org.eclipse.glsp.graph.builder.impl.GPreRenderedElementBuilder;
import org.eclipse.glsp.server.features.popup.PopupModelFactory;
import org.eclipse.glsp.server.features.popup.RequestPopupModelAction;
import org.kse.model.statechart.Node;
import org.kse.model.statechart.Transition;

import com.google.inject.Inject;

/** Hovering shows what the diagram abbreviates: a transition's whole expression, a state's label, kind and activity. */
public class StatechartPopups implements PopupModelFactory {

	@Inject
	private StatechartModelState state;

	@Override
	public Optional<GHtmlRoot> createPopupModel(GModelElement element, RequestPopupModelAction action) {
		return state.read(() -> popup(element, action));
	}

	private Optional<GHtmlRoot> popup(GModelElement element, RequestPopupModelAction action) {
		EObject model = state.element(element.getId());
		String html;
		if (model instanceof Transition transition) {
			String expression = transition.getTE() == null || transition.getTE().isBlank() ? "(no expression: taken at once)" : transition.getTE().strip();
			html = "<div class=\"kse-popup\"><div class=\"kse-popup-title\">" + escape(transition.getName()) + "</div><pre>" + escape(expression) + "</pre></div>";
		} else if (model instanceof Node node) {
			String activity = node.getActivity() == null || node.getActivity().isBlank() ? "" : "<div>activity " + escape(node.getActivity()) + "</div>";
			html = "<div class=\"kse-popup\"><div class=\"kse-popup-title\">" + escape(node.getLabel()) + " " + escape(node.getName()) + "</div><div>"
					+ escape(node.getType()) + " state</div>" + activity + "</div>";
		} else {
			return Optional.empty();
		}
		return Optional.of(new GHtmlRootBuilder().id("popup").add(new GPreRenderedElementBuilder().id("popup-body").code(html).build())
				.canvasBounds(action.getBounds()).build());
	}

	private static String escape(String text) {
		return text == null ? "" : text.replace("&", "&amp;").replace("<", "&lt;").replace(">", "&gt;").replace("\"", "&quot;");
	}
}
