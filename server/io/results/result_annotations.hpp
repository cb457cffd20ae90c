#pragma once
/// What the result document carries for people reading it, beyond the solver's numbers: the names of
/// the model's units, and each gap's contact pressure. Kept apart from the writer so that the
/// writer adds the same two things the same way wherever it writes them.
///
/// contact_pressure = max(0, -sigma_m): the compressive normal stress across a gap, positive, and 0
/// where the gap carries tension. sigma_m is negative in compression in both gap methods (the
/// stress-invariance iteration and the exact contact mode), so one definition serves both.

#include "io/json/json_writer.hpp"
#include "solver/model/model.hpp"

namespace saasgaps::io {

/// Writes the member "units": {"force": .., "length": .., "stress": .., "temperature": ..} with
/// only the names the model gives (keys in alphabetical order); nothing when it gives none.
void write_units(JsonWriter& out, const Units& units);

/// max(0, -sigma_m), stress units of the model.
double contact_pressure(double sigma_m);

}  // namespace saasgaps::io
