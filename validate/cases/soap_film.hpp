#pragma once
// The membrane cases' one formulation: patch b in CST form-finding with the
// equal warp and weft stress sigma [N/m] (a soap film, eq. 3.36) on the given
// triangles.
#include <vector>

#include "model/model.hpp"

namespace tendril::validate {

inline void make_soap_film(Model& m, BlockId b, double sigma, const std::vector<Model::Triangle>& triangles) {
  Membrane film;
  film.mode = Membrane::FormFinding;
  film.sigma_warp = film.sigma_weft = sigma;
  m.set_patch_formulation(b, film, triangles);
}

}  // namespace tendril::validate
