// The interpreter's Setup from a machine configuration (machine/machine.hpp): what it needs of
// the machine, in its own terms. `kerf run` uses the built-in machine of the dialect unless told
// otherwise.
#pragma once

#include "dialects/dialect.hpp"
#include "interpreter/setup.hpp"
#include "machine/machine.hpp"

namespace kerf::interpreter {

Setup make_setup(const machine::Machine& machine);
// The built-in machine of the dialect (machine::default_machine_for).
Setup default_setup(const dialects::Dialect& dialect);

}  // namespace kerf::interpreter
