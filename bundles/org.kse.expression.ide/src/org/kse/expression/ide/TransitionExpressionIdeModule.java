/*
 * Hand-written; created once from the Xtext template.
 */
package org.kse.expression.ide;


/**
 * Use this class to register ide components.
 */
public class TransitionExpressionIdeModule extends AbstractTransitionExpressionIdeModule {
}
