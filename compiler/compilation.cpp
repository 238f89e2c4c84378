#include "compilation.hpp"

#include <ostream>

#include "diagnostics.hpp"
#include "import_loader.hpp"
#include "semantic_checker.hpp"

namespace acanthus {

bool compile_rule_file(const CompileRequest& request, bool generate_code, std::string& cpp,
                       std::ostream& diagnostics_out, std::vector<std::string>* read_files,
                       std::vector<ParamSummary>* params, GeneratedUnits* units) {
    SourceFiles files;
    Diagnostics diagnostics(files);
    ImportLoader loader(files, diagnostics, request.include_dirs, request.stdlib_dirs);
    std::string error;
    if (!loader.load(request.input, error)) {
        diagnostics_out << "acanthus: error: cannot read '" << request.input << "': " << error
                        << '\n';
        return false;
    }
    if (read_files)
        for (std::uint32_t i = 0; i < files.size(); ++i) read_files->push_back(files[i].path());
    PatternModel model = check_program(loader.program(), files, diagnostics);
    if (diagnostics.error_count() > 0) {
        diagnostics.print(diagnostics_out);
        return false;
    }
    if (params) {
        for (const ParamModel& p : model.params) {
            ParamSummary summary{p.decl->name.text, std::string(p.type.info),
                                 p.decl->default_value.text, "", ""};
            if (p.decl->range) {
                summary.low = p.decl->range->low.text;
                summary.high = p.decl->range->high.text;
            }
            params->push_back(std::move(summary));
        }
    }
    if (generate_code) cpp = generate_cpp(model, files, request.generate);
    if (generate_code && units) *units = generate_cpp_units(model, files, request.generate);
    return true;
}

}  // namespace acanthus
