#pragma once
// MODELS.DAT: finite-element models of MAILx bodies. spec: datbox-inputs.md §4.
#include <vector>

#include "grammar/common/field.hpp"

namespace lmgc::grammar {

struct ModelOption {
  Word id;                 // columns 23-27: isext, kine_, form_, ... ('ext_f' is read as 'extsf')
  Word value;              // columns 30-59 (A30); u_mdl: the user model name (list-directed, 30-79)
  Integer vfield_size;     // columns 61-65, only for 'extvf' options
  friend bool operator==(const ModelOption&, const ModelOption&) = default;
};

struct Model {
  Word nickname;  // columns 2-6, referred to by the 'model' lines of MAILx elements
  Word kind;      // columns 9-13: MECAx, THERM, POROx, MULTI
  Word element;   // columns 16-20: Q4xxx, T3xxx, H8xxx, ...
  std::vector<ModelOption> options;
  friend bool operator==(const Model&, const Model&) = default;
};

struct ModelsFile {
  std::vector<Model> models;
  friend bool operator==(const ModelsFile&, const ModelsFile&) = default;
};

}  // namespace lmgc::grammar
