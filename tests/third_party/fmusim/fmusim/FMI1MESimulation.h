#pragma once

#include "FMISimulation.h"


FMIStatus FMI1MESimulate(const FMISimulationSettings* s);
