#include <acanthus/environment.hpp>

namespace acanthus {
namespace {
thread_local Environment* current_environment = nullptr;
}

Environment* Environment::current() { return current_environment; }

Environment::Scope::Scope(Environment* env) : previous_(current_environment) {
    current_environment = env;
}

Environment::Scope::~Scope() { current_environment = previous_; }

}  // namespace acanthus
