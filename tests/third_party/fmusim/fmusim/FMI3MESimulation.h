#pragma once

#include "FMISimulation.h"


FMIStatus FMI3MESimulate(const FMISimulationSettings* s);
