#pragma once

// The 4-connected pieces of a 2-D predicate on an nx x ny slice (pixel index i + nx * j): shared by the aortic
// lumen tracking (AneurysmSac.cpp) and the automatic aorta point (AortaFinder.cpp).

#include <cstdint>
#include <utility>
#include <vector>

namespace vsim::imaging::detail {

template <typename Inside>
std::vector<std::vector<std::uint32_t>> slicePieces(int nx, int ny, const Inside& inside)
{
    std::vector<std::uint8_t> seen(std::size_t(nx) * std::size_t(ny), 0);
    std::vector<std::vector<std::uint32_t>> pieces;
    for (int j = 0; j < ny; ++j)
        for (int i = 0; i < nx; ++i)
        {
            const std::uint32_t start = std::uint32_t(i + nx * j);
            if (seen[start] || !inside(i, j))
                continue;
            std::vector<std::uint32_t> piece{start}, stack{start};
            seen[start] = 1;
            while (!stack.empty())
            {
                const std::uint32_t p = stack.back();
                stack.pop_back();
                const int pi = int(p % std::uint32_t(nx)), pj = int(p / std::uint32_t(nx));
                for (const auto& [di, dj] : {std::pair{1, 0}, std::pair{-1, 0}, std::pair{0, 1}, std::pair{0, -1}})
                {
                    const int ii = pi + di, jj = pj + dj;
                    if (ii < 0 || jj < 0 || ii >= nx || jj >= ny)
                        continue;
                    const std::uint32_t q = std::uint32_t(ii + nx * jj);
                    if (!seen[q] && inside(ii, jj))
                        seen[q] = 1, piece.push_back(q), stack.push_back(q);
                }
            }
            pieces.push_back(std::move(piece));
        }
    return pieces;
}

} // namespace vsim::imaging::detail
