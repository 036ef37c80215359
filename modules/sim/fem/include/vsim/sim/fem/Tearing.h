#pragma once

// Tearing of the wall (thesis ch. 4.6): an element whose largest principal stress passes the tear strength (the
// thesis's "tear factor" as a stress limit) is detached, and every node that the fracture separates is split into
// one copy per side (the elements left around it fall into groups that share no face through it).
//
// End condition (thesis eq. 4.23, which lacks its minus sign): the entropy S = -sum_i p_i ln p_i (c = 1, nats) of
// the fracture, with p_i the share of element i in the elastic energy released by all torn elements so far
// (the energy element i held when it tore). e^S is the effective number of torn elements: a single tear gives
// S = 0, k tears that release equal energy give ln k. The run stops tearing once S passes a threshold.

#include "vsim/sim/fem/CorotationalFem.h"

#include <cstdint>
#include <vector>

namespace vsim::sim::fem {

/// Elements (not yet in `torn`) whose largest principal stress exceeds `tearStressPa`, most stressed first.
std::vector<std::size_t> elementsOverStrength(const ElementStresses& stresses, double tearStressPa);

/// A model without the `torn` elements, its separated nodes split and orphaned nodes dropped.
struct DetachedModel
{
    CorotationalFem model;
    std::vector<int> oldNodeOf;            ///< for each new node, the node it came from
    std::vector<std::size_t> oldElementOf; ///< for each new element, its index before
    std::size_t splitNodes = 0;            ///< nodes added by splitting
};

/// Removes `torn` (element indices of `model`) and carries positions and velocities over. Throws vsim::Error
/// when no element would be left.
DetachedModel detachElements(const CorotationalFem& model, const std::vector<std::size_t>& torn);

/// The fracture entropy above.
class FractureEntropy
{
public:
    /// Adds a torn element that held `releasedEnergyJ` (> 0) when it tore.
    void addTornElement(double releasedEnergyJ);
    /// S = -sum p ln p (nats); 0 with fewer than two tears.
    double value() const;
    /// e^S.
    double effectiveCount() const;
    std::size_t tornElements() const { return m_energies.size(); }

private:
    std::vector<double> m_energies;
};

} // namespace vsim::sim::fem
