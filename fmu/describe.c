/* modelDescription.xml of the FMU, written from the table the binary serves (variables.c):
 * FMI 2.0 section 2.2 (the model description schema) and 4.3 (co-simulation capabilities).
 * SPDX-License-Identifier: Apache-2.0 */
#include <stdio.h>
#include <string.h>

#include "fmu_impl.h"

static void xml_text(FILE *fp, const char *s)
{
    for (; *s; ++s)
        switch (*s) {
        case '&': fputs("&amp;", fp); break;
        case '<': fputs("&lt;", fp); break;
        case '>': fputs("&gt;", fp); break;
        case '"': fputs("&quot;", fp); break;
        default: fputc(*s, fp);
        }
}

static const char *causality_name(fmu_causality c)
{
    return c == FMU_PARAMETER ? "parameter" : c == FMU_INPUT ? "input" : "output";
}

int fmu__describe(FILE *fp)
{
    size_t n;
    const fmu_variable *vars = fmu__variables(&n);
    const fmu_values start = fmu__start_values();
    char guid[64];
    fprintf(fp, "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
                "<fmiModelDescription fmiVersion=\"2.0\" modelName=\"%s\" guid=\"%s\"\n"
                "  description=\"The effective road of a tire (quasi-static enveloping) at a "
                "wheel-centre position and vertical load\"\n"
                "  generationTool=\"tirenv %s\" version=\"%s\" license=\"Apache-2.0\"\n"
                "  copyright=\"Copyright 2026 the tirenv authors\"\n"
                "  variableNamingConvention=\"flat\" numberOfEventIndicators=\"0\">\n",
            FMU_MODEL_IDENTIFIER, fmu__guid(guid, sizeof guid), TIRENV_VERSION,
            TIRENV_VERSION);
    /* A static map: outputs are computed at each step from the inputs, no state to
     * integrate, any step size; the warm start is saved and restored with the FMU state. */
    fprintf(fp, "  <CoSimulation modelIdentifier=\"%s\" needsExecutionTool=\"false\"\n"
                "    canHandleVariableCommunicationStepSize=\"true\" canInterpolateInputs=\"false\"\n"
                "    maxOutputDerivativeOrder=\"0\" canRunAsynchronuously=\"false\"\n"
                "    canBeInstantiatedOnlyOncePerProcess=\"false\" canNotUseMemoryManagementFunctions=\"false\"\n"
                "    canGetAndSetFMUstate=\"true\" canSerializeFMUstate=\"true\"\n"
                "    providesDirectionalDerivative=\"false\"/>\n",
            FMU_MODEL_IDENTIFIER);
    fputs("  <UnitDefinitions>\n"
          "    <Unit name=\"m\"><BaseUnit m=\"1\"/></Unit>\n"
          "    <Unit name=\"N\"><BaseUnit kg=\"1\" m=\"1\" s=\"-2\"/></Unit>\n"
          "  </UnitDefinitions>\n"
          "  <LogCategories>\n"
          "    <Category name=\"logStatusError\" description=\"why a call returned fmi2Error\"/>\n"
          "    <Category name=\"logAll\" description=\"setup and every other message\"/>\n"
          "  </LogCategories>\n"
          "  <DefaultExperiment startTime=\"0\"/>\n"
          "  <ModelVariables>\n", fp);
    for (size_t i = 0; i < n; ++i) {
        const fmu_variable *v = &vars[i];
        fprintf(fp, "    <!-- index %zu -->\n    <ScalarVariable name=\"", i + 1);
        xml_text(fp, v->name);
        fprintf(fp, "\" valueReference=\"%u\" causality=\"%s\" variability=\"%s\"", v->vr,
                causality_name(v->causality),
                v->causality == FMU_PARAMETER ? "fixed" : "continuous");
        if (v->causality == FMU_OUTPUT)
            fputs(" initial=\"calculated\"", fp);
        fputs("\n      description=\"", fp);
        xml_text(fp, v->description);
        fputs("\">\n", fp);
        const char *value = (const char *)&start + v->offset;
        if (v->type == FMU_STRING) {
            fputs("      <String start=\"", fp);
            xml_text(fp, value);
            fputs("\"/>\n", fp);
        } else {
            fputs("      <Real", fp);
            if (v->unit)
                fprintf(fp, " unit=\"%s\"", v->unit);
            if (v->causality != FMU_OUTPUT) {
                double d;
                memcpy(&d, value, sizeof d);
                fprintf(fp, " start=\"%.17g\"", d);
            }
            fputs("/>\n", fp);
        }
        fputs("    </ScalarVariable>\n", fp);
    }
    fputs("  </ModelVariables>\n  <ModelStructure>\n    <Outputs>\n", fp);
    /* Every output depends on both inputs, directly (a static map); indices are 1-based. */
    size_t ix = 0, iload = 0;
    for (size_t i = 0; i < n; ++i) {
        if (strcmp(vars[i].name, "x") == 0)
            ix = i + 1;
        if (strcmp(vars[i].name, "load") == 0)
            iload = i + 1;
    }
    for (size_t i = 0; i < n; ++i)
        if (vars[i].causality == FMU_OUTPUT)
            fprintf(fp, "      <Unknown index=\"%zu\" dependencies=\"%zu %zu\"/>\n", i + 1, ix,
                    iload);
    /* At initialization they depend on the parameters too: no list means all knowns. */
    fputs("    </Outputs>\n    <InitialUnknowns>\n", fp);
    for (size_t i = 0; i < n; ++i)
        if (vars[i].causality == FMU_OUTPUT)
            fprintf(fp, "      <Unknown index=\"%zu\"/>\n", i + 1);
    fputs("    </InitialUnknowns>\n", fp);
    fputs("  </ModelStructure>\n</fmiModelDescription>\n", fp);
    return ferror(fp) ? -1 : 0;
}
