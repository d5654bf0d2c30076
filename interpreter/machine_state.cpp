#include "interpreter/machine_state.hpp"

namespace kerf::interpreter {

// Power-on state (semantics.md §1.3): the codes marked as defaults in the dialect table, then the
// machine's power-on switches over the table (machine/SCHEMA.md "Power-on state").
MachineState::MachineState(const dialects::Dialect& dialect, const Setup& setup)
    : work_offsets(setup.work_offsets), external_offset(setup.external_offset), work_shift(setup.work_shift),
      radius_comp(setup.radius_comp), cycle_parameters(setup.cycles.initial) {
    modal.assign(dialect.groups().size(), nullptr);
    for (const dialects::CodeInfo& c : dialect.codes())
        if (c.letter == 'G' && c.power_on_default && c.group != "00") modal[c.group_index] = &c;
    for (const dialects::FunctionId function : setup.power_on)
        for (const dialects::CodeInfo* c : dialect.codes_with_function(function))
            if (c->letter == 'G' && !c->group.empty() && c->group != "00") modal[c->group_index] = c;
}

}  // namespace kerf::interpreter
