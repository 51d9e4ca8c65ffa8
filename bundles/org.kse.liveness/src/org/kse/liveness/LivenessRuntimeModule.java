/*
 * Hand-written; created once from the Xtext template.
 */
package org.kse.liveness;


/**
 * Use this class to register components to be used at runtime / without the Equinox extension registry.
 */
public class LivenessRuntimeModule extends AbstractLivenessRuntimeModule {
}
