#include "vsim/core/ParticleSet.h"

#include "vsim/core/Error.h"

namespace vsim {

void ParticleSet::validate() const
{
    for (const auto& [name, values] : fields)
        if (values.size() != positionsMm.size())
            throw Error(Pattern{"the particle field %1 has %2 values for %3 particles",
                                {name, std::to_string(values.size()), std::to_string(positionsMm.size())}});
}

} // namespace vsim
