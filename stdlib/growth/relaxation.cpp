#include "relaxation.hpp"

#include <Eigen/Sparse>
#include <Eigen/SparseCholesky>
#include <algorithm>
#include <map>

namespace acanthus::growth::detail {

void relax(std::vector<Point>& positions, const std::vector<Spring>& springs,
           const std::vector<int>& free_nodes, double stiffness) {
    if (free_nodes.empty()) return;
    std::map<int, int> column;  // node -> unknown
    for (int node : free_nodes) column.emplace(node, static_cast<int>(column.size()));
    const int n = static_cast<int>(free_nodes.size());
    std::vector<Eigen::Triplet<double>> entries;
    Eigen::VectorXd bx = Eigen::VectorXd::Zero(n), by = Eigen::VectorXd::Zero(n);
    for (int k = 0; k < n; ++k) {
        Point p = positions[free_nodes[k]];
        entries.emplace_back(k, k, stiffness);
        bx[k] += stiffness * p.x;
        by[k] += stiffness * p.y;
    }
    // Normal equations of |x_to - x_from - d|^2: +1 on the diagonals, -1 off them; a held end
    // moves to the right-hand side.
    for (const Spring& s : springs) {
        auto from = column.find(s.from), to = column.find(s.to);
        bool free_from = from != column.end(), free_to = to != column.end();
        if (!free_from && !free_to) continue;
        if (free_from && free_to) {
            int a = from->second, b = to->second;
            entries.emplace_back(a, a, 1.0);
            entries.emplace_back(b, b, 1.0);
            entries.emplace_back(a, b, -1.0);
            entries.emplace_back(b, a, -1.0);
            bx[b] += s.desired.x;
            by[b] += s.desired.y;
            bx[a] -= s.desired.x;
            by[a] -= s.desired.y;
        } else if (free_to) {
            int b = to->second;
            Point held = positions[s.from];
            entries.emplace_back(b, b, 1.0);
            bx[b] += held.x + s.desired.x;
            by[b] += held.y + s.desired.y;
        } else {
            int a = from->second;
            Point held = positions[s.to];
            entries.emplace_back(a, a, 1.0);
            bx[a] += held.x - s.desired.x;
            by[a] += held.y - s.desired.y;
        }
    }
    Eigen::SparseMatrix<double> matrix(n, n);
    matrix.setFromTriplets(entries.begin(), entries.end());
    Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> solver(matrix);
    if (solver.info() != Eigen::Success) return;
    Eigen::VectorXd x = solver.solve(bx), y = solver.solve(by);
    if (solver.info() != Eigen::Success || !x.allFinite() || !y.allFinite()) return;
    for (int k = 0; k < n; ++k) positions[free_nodes[k]] = {x[k], y[k]};
}

}  // namespace acanthus::growth::detail
