/*
 * Hand-written; started from the Xtext template.
 */
package org.kse.expression;


/**
 * Use this class to register components to be used at runtime / without the Equinox extension registry.
 */
public class TransitionExpressionRuntimeModule extends AbstractTransitionExpressionRuntimeModule {
}
