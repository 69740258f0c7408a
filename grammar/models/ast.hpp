#pragma once
// MODELS.DAT: finite-element models of MAILx bodies. docs/lmgc90-facts/datbox-inputs.md §4.
#include <vector>

#include "grammar/common/field.hpp"

namespace lmgc::grammar {

struct ModelOption {
  Word id;     // columns 23-27: isext, kine_, form_, ... ('ext_f' is read as 'extsf')
  Word value;  // columns 30-59 (A30), trailing blanks removed
  friend bool operator==(const ModelOption&, const ModelOption&) = default;
};

struct Model {
  Word nickname;  // columns 2-6, referred to by the 'model' lines of MAILx elements
  Word kind;      // mdlty, columns 9-13: MECAx, THERM, POROx, MULTI
  Word element;   // finel, columns 16-20: Q4xxx, T3xxx, H8xxx, ...
  Word
      user_model;  // 'u_mdl' as the first option: user model name (list-directed from 30-79); empty otherwise
  std::vector<ModelOption> options;  // in file order ('u_mdl' of the mdlty line excluded)
  // Largest size read at 61-65 on the option lines after the mdlty line (0 when none): LMGC90
  // keeps one size per model and writes it on every 'extvf' option line.
  Integer vfield_max_size;
  friend bool operator==(const Model&, const Model&) = default;
};

struct ModelsFile {
  std::vector<Model> models;
  friend bool operator==(const ModelsFile&, const ModelsFile&) = default;
};

}  // namespace lmgc::grammar
