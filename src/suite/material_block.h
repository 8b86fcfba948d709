// The suite's "material" block: which material model its bodies use (softbody/material.h), read and checked
// against the rest of the suite. Its own file: the suite reader stays the reader of the suite's shape.
#pragma once

#include <nlohmann/json.hpp>

#include "suite/suite_fields.h"

namespace tcsb {

/// Reads root's "material" (absent: Bullet's model, every suite before it) into s.solver, after the nets and
/// methods are read: under the compliant model every net's mass becomes the material's density (a net's own
/// "mass" is refused), and the "stock" method needs it. `nets` is the suite's "nets" array as written. Throws
/// InputError naming the field.
void parse_material(const suite_fields::Reader& r, const suite_fields::Object& root, const nlohmann::json& nets,
                    Suite& s);

/// The checks that need the whole suite read (its calibration, its TC-SB settings, its kLST): after everything else.
void check_material(const suite_fields::Reader& r, const Suite& s);

/// "bullet" or "compliant".
const char* material_model_name(MaterialModel model);

}  // namespace tcsb
