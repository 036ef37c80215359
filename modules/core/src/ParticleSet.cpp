#include "vsim/core/ParticleSet.h"

#include "vsim/core/Error.h"

namespace vsim {

void ParticleSet::validate() const
{
    for (const auto& [name, values] : fields)
        if (values.size() != positionsMm.size())
            throw Error("the particle field " + name + " has " + std::to_string(values.size()) + " values for " +
                        std::to_string(positionsMm.size()) + " particles");
}

} // namespace vsim
