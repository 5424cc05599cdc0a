#pragma once

#include "FMISimulation.h"


FMIStatus FMI2CSSimulate(const FMISimulationSettings* s);
