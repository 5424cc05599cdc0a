#pragma once

#include "FMISimulation.h"


FMIStatus FMI3CSSimulate(const FMISimulationSettings* settings);
