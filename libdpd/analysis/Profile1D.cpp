#include "analysis/Profile1D.hpp"


namespace dpd {

Profile1D selectProfilePoints(const Profile1D& p, const std::function<double(double)>& coordinate,
                              const std::function<bool(double)>& keep) {
    Profile1D s;
    s.blocks.resize(p.blocks.size());
    for (std::size_t i = 0; i < p.y.size(); ++i) {
        const double y = coordinate(p.y[i]);
        if (!keep(y)) continue;
        s.y.push_back(y);
        s.u.push_back(p.u[i]);
        if (!p.uErr.empty()) s.uErr.push_back(p.uErr[i]);
        for (std::size_t k = 0; k < p.blocks.size(); ++k) s.blocks[k].push_back(p.blocks[k].at(i));
    }
    return s;
}

PolyFitResult fitProfilePolynomial(const Profile1D& p, int degree) {
    if (p.blocks.empty()) return fitPolynomial(p.y, p.u, p.uErr, degree, true);
    return fitPolynomial(p.y, p.u, p.uErr, degree, p.blocks);
}

}  // namespace dpd
