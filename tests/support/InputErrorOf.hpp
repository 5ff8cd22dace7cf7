#pragma once
// For tests of refused input: the message of the InputError a call throws.
#include "core/Error.hpp"

#include <string>
#include <utility>

namespace dpd::test {

// What `call` says when it refuses its input ("" when it throws no InputError).
template <class Call>
std::string inputErrorOf(Call&& call) {
    try {
        std::forward<Call>(call)();
    } catch (const InputError& e) {
        return e.what();
    }
    return "";
}

}  // namespace dpd::test
