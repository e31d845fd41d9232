#include "rank_errors.hpp"

#include "commands.hpp"

#include "roughgas/io/input_error.hpp"

#include <iostream>

namespace roughgas::cli {

int report_error(std::exception_ptr error, std::ostream& out, const std::string& prefix) {
    // Each message is put together first and written at once: std::cerr is unbuffered, and a
    // message written piece by piece can be cut by the output of the launcher or of other ranks.
    std::string line;
    int status = exit_failure;
    try {
        std::rethrow_exception(error);
    } catch (const QuietExit& q) {
        return q.status;
    } catch (const InputError& e) {
        line = (prefix.empty() ? "" : "roughgas: " + prefix) + e.what() + "\n";
        status = exit_invalid;
    } catch (const std::exception& e) {
        line = "roughgas: " + prefix + "error: " + e.what() + "\n";
    } catch (...) {
        line = "roughgas: " + prefix + "unknown error\n";
    }
    out << line;
    out.flush();
    return status;
}

void agree_on_setup(const Communicator& comm, const std::function<void()>& setup) {
    std::exception_ptr error;
    try {
        setup();
    } catch (...) {
        error = std::current_exception();
    }
    if (comm.size() == 1) {
        if (error)
            std::rethrow_exception(error);
        return;
    }
    // The lowest failing rank (size - rank is largest for it), then its status.
    const long long first = comm.size() - comm.max(error ? comm.size() - comm.rank() : 0);
    if (first == comm.size())
        return;
    int status = 0;
    if (comm.rank() == first) {
        status = report_error(error, std::cerr);
        std::cerr.flush();
    }
    throw QuietExit{static_cast<int>(comm.max(status))};
}

} // namespace roughgas::cli
