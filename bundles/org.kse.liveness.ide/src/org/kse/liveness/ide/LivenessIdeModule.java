/*
 * Hand-written; created once from the Xtext template.
 */
package org.kse.liveness.ide;


/**
 * Use this class to register ide components.
 */
public class LivenessIdeModule extends AbstractLivenessIdeModule {
}
