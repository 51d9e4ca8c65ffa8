package org.kse.validation;

import java.util.HashMap;
import java.util.Map;

import org.eclipse.emf.common.util.BasicDiagnostic;
import org.eclipse.emf.common.util.Diagnostic;
import org.eclipse.emf.ecore.EValidator;
import org.eclipse.emf.ecore.impl.EValidatorRegistryImpl;
import org.eclipse.emf.ecore.util.Diagnostician;
import org.kse.expression.ExpressionParser;
import org.kse.messages.MessageCatalog;
import org.kse.model.statechart.Model;
import org.kse.model.statechart.StatechartPackage;

/** Headless validation of a whole model with the KSE rules. */
public final class ModelValidation {

	private ModelValidation() {
	}

	/** All diagnostics of the model, messages checked against the standard catalog. */
	public static Diagnostic validate(Model model) {
		return validate(model, null);
	}

	/**
	 * All diagnostics of the model, as children of the returned diagnostic, in document
	 * order; transition expressions and variables are checked against {@code catalog}
	 * (the standard messages when null).
	 */
	public static Diagnostic validate(Model model, MessageCatalog catalog) {
		return validate(model, catalog, ExpressionParser.session());
	}

	/**
	 * As {@link #validate(Model, MessageCatalog)}, parsing the expressions with {@code expressions},
	 * whose parses the caller then reuses (the generator plans its C++ from them).
	 */
	public static Diagnostic validate(Model model, MessageCatalog catalog, ExpressionParser.Session expressions) {
		EValidator.Registry registry = new EValidatorRegistryImpl();
		registry.put(StatechartPackage.eINSTANCE, new StatechartValidator());
		Diagnostician diagnostician = new Diagnostician(registry) {
			@Override
			public String getObjectLabel(org.eclipse.emf.ecore.EObject eObject) {
				return Labels.describe(eObject);
			}
		};
		BasicDiagnostic result = diagnostician.createDefaultDiagnostic(model);
		Map<Object, Object> context = new HashMap<>(diagnostician.createDefaultContext());
		if (catalog != null) {
			context.put(StatechartValidator.CATALOG, catalog);
		}
		context.put(StatechartValidator.EXPRESSIONS, expressions);
		diagnostician.validate(model, result, context);
		return result;
	}
}
