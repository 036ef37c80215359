#include "CalculixJob.h"

#include "vsim/core/Error.h"
#include "vsim/sim/fem/ElementStresses.h"

#include <fstream>
#include <set>
#include <sstream>
#include <string>

namespace vsim::bench {

int calculixFace(const std::array<int, 4>& tet, const std::array<int, 3>& face)
{
    static const int corners[4][3] = {{0, 1, 2}, {0, 3, 1}, {1, 3, 2}, {2, 3, 0}};
    const std::set<int> wanted(face.begin(), face.end());
    for (int f = 0; f < 4; ++f)
        if (std::set<int>{tet[std::size_t(corners[f][0])], tet[std::size_t(corners[f][1])], tet[std::size_t(corners[f][2])]} == wanted)
            return f + 1;
    return 0;
}

void writeCalculixInput(const CalculixJob& job, const std::filesystem::path& file)
{
    std::ofstream out(file);
    out.precision(12);
    out << "** VascuSim bench_fem_calculix: mm, N, MPa\n*NODE, NSET=NALL\n";
    for (std::size_t n = 0; n < job.nodesMm.size(); ++n)
        out << n + 1 << ", " << job.nodesMm[n].x() << ", " << job.nodesMm[n].y() << ", " << job.nodesMm[n].z() << "\n";
    const bool quadratic = !job.elements.empty() && job.elements.front().size() == 10;
    out << "*ELEMENT, TYPE=" << (quadratic ? "C3D10" : "C3D4") << ", ELSET=EALL\n";
    for (std::size_t e = 0; e < job.elements.size(); ++e)
    {
        out << e + 1;
        for (std::size_t k = 0; k < job.elements[e].size(); ++k)
            // A data line holds at most 16 entries: C3D10's last node goes on the next line.
            out << (k == 15 ? ",\n" : ", ") << job.elements[e][k] + 1;
        out << "\n";
    }
    out << "*NSET, NSET=FIXED\n";
    for (std::size_t n = 0; n < job.nodesMm.size(); ++n)
        if (job.fixedNodes[n])
            out << n + 1 << ",\n";
    out << "*BOUNDARY\nFIXED, 1, 3\n*MATERIAL, NAME=WALL\n";
    if (job.material == CalculixJob::Material::Elastic)
        out << "*ELASTIC\n" << job.youngMpa << ", " << job.poisson << "\n";
    else
        out << "*HYPERELASTIC, REDUCED POLYNOMIAL, N=2\n" << job.c10Mpa << ", " << job.c20Mpa << ", " << job.d1PerMpa
            << ", 0.\n";
    out << "*SOLID SECTION, ELSET=EALL, MATERIAL=WALL\n"
        << (job.nlgeom ? "*STEP, NLGEOM, INC=200\n*STATIC\n0.25, 1.\n"
                         // Residual (R_n) and correction (C_n) criteria tightened from 0.5 % and 1 % (defaults) to 1e-7.
                         "*CONTROLS, PARAMETERS=FIELD\n1.e-7, 1.e-7\n"
                       : "*STEP\n*STATIC\n")
        << "*DLOAD\n";
    for (const auto& [element, face] : job.pressureFaces)
        out << element + 1 << ", P" << face << ", " << job.pressurePa * 1e-6 << "\n";
    out << "*NODE PRINT, NSET=NALL\nU\n*EL PRINT, ELSET=EALL\nS\n*END STEP\n";
}

CalculixResults readCalculixResults(const std::filesystem::path& file, std::size_t nodes, std::size_t elements)
{
    std::ifstream in(file);
    if (!in)
        throw Error("CalculiX wrote no " + file.string());
    CalculixResults results;
    results.displacementMm = Eigen::VectorXd::Zero(Eigen::Index(3 * nodes));
    std::vector<Eigen::Matrix3d> sums(elements, Eigen::Matrix3d::Zero());
    std::vector<int> points(elements, 0);
    std::string line, block;
    std::size_t displacements = 0;
    while (std::getline(in, line))
    {
        // NLGEOM prints every increment: each header starts the block again, the last one is the result.
        if (line.find("displacements") != std::string::npos)
            block = "u", displacements = 0;
        else if (line.find("stresses") != std::string::npos)
        {
            block = "s";
            std::fill(sums.begin(), sums.end(), Eigen::Matrix3d::Zero());
            std::fill(points.begin(), points.end(), 0);
        }
        std::istringstream fields(line);
        if (block == "u")
        {
            long node;
            double ux, uy, uz;
            if (fields >> node >> ux >> uy >> uz && node >= 1 && std::size_t(node) <= nodes)
                results.displacementMm.segment<3>(Eigen::Index(3 * (node - 1))) = Eigen::Vector3d(ux, uy, uz), ++displacements;
        }
        else if (block == "s")
        {
            // "element point sxx syy szz sxy sxz syz"
            long element, point;
            double xx, yy, zz, xy, xz, yz;
            if (fields >> element >> point >> xx >> yy >> zz >> xy >> xz >> yz && element >= 1 &&
                std::size_t(element) <= elements)
            {
                Eigen::Matrix3d s;
                s << xx, xy, xz, xy, yy, yz, xz, yz, zz;
                sums[std::size_t(element - 1)] += s;
                ++points[std::size_t(element - 1)];
            }
        }
    }
    const std::size_t withStress = std::size_t(std::count_if(points.begin(), points.end(), [](int p) { return p > 0; }));
    if (displacements != nodes || withStress != elements)
        throw Error("CalculiX's results are incomplete: " + std::to_string(displacements) + " of " + std::to_string(nodes) +
                    " displacements, " + std::to_string(withStress) + " of " + std::to_string(elements) +
                    " element stresses");
    results.vonMisesMpa.resize(elements);
    for (std::size_t e = 0; e < elements; ++e)
        results.vonMisesMpa[e] = sim::fem::vonMisesOf(sums[e] / points[e]);
    return results;
}

} // namespace vsim::bench
