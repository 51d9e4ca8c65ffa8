/**
 * SCXML (W3C State Chart XML) out of and into KSE statecharts: the export writes a chart that
 * any SCXML processor runs with the transitions the Monas engine takes (docs/adr/0038-scxml-mapping.md);
 * the import reads charts written by other tools into a model, or says per element why it cannot.
 */
package org.kse.scxml;
