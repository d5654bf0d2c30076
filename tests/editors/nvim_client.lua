-- The Neovim real-client test (issue 14 "What must be shown" 2): Neovim's own LSP client, started
-- by editors/nvim (require('kerf').setup), opens the sample lathe program with defects, waits for
-- the diagnostics, asks hover, definition (into another file of the folder) and formatting, and
-- writes what it got to $KERF_OUT; tests/editors/run_nvim.sh compares that with
-- tests/editors/nvim_client.expected (reviewed by hand).
--
--   KERF_BINARY=... KERF_WORKSPACE=... KERF_OUT=... nvim --headless -u NONE -i NONE \
--       --cmd 'set rtp+=editors/nvim' -c 'luafile tests/editors/nvim_client.lua'
local out = {}
local function say(line) table.insert(out, line) end
local function finish(code)
  local f = io.open(os.getenv('KERF_OUT'), 'w')
  f:write(table.concat(out, '\n') .. '\n')
  f:close()
  vim.cmd(code == 0 and 'qall!' or 'cquit!')
end
local function fail(why)
  say('FAILED: ' .. why)
  finish(1)
end
local function span(r) return string.format('%d:%d-%d:%d', r.start.line, r.start.character, r['end'].line, r['end'].character) end
local function tail(uri) return uri:match('([^/]+)$') end

local ok, err = pcall(function()
  local indexed = false
  local exit_code
  require('kerf').setup({
    cmd = { os.getenv('KERF_BINARY'), 'lsp' },
    handlers = {
      ['window/logMessage'] = function(_, result)
        if result.message:find('kerf lsp: indexed', 1, true) then indexed = true end
      end,
    },
  })
  local workspace = os.getenv('KERF_WORKSPACE')
  vim.cmd('edit ' .. workspace .. '/main.nc')
  local buf = vim.api.nvim_get_current_buf()
  say('filetype: ' .. vim.bo[buf].filetype)

  local client
  if not vim.wait(20000, function()
    client = vim.lsp.buf_get_clients(buf)[1]
    return client ~= nil and client.initialized and indexed
  end, 50) then return fail('the server did not start and index') end
  client.config.on_exit = function(code) exit_code = code end
  say('server: ' .. client.name)

  -- Every scheduled analysis done: the complete diagnostics were sent before this answer.
  local waited = client.request_sync('kerf/waitForAnalysis', nil, 30000, buf)
  if not waited or waited.err then return fail('kerf/waitForAnalysis') end
  vim.wait(200)
  local diagnostics = vim.diagnostic.get(buf)
  table.sort(diagnostics, function(a, b) return a.lnum < b.lnum or (a.lnum == b.lnum and a.col < b.col) end)
  for _, d in ipairs(diagnostics) do
    say(string.format('diagnostic %d:%d %s severity %d: %s', d.lnum, d.col, d.code or '?', d.severity, (d.message:gsub('\n.*', ''))))
  end

  local function at(line, col)
    return { textDocument = { uri = vim.uri_from_bufnr(buf) }, position = { line = line, character = col } }
  end
  local hover = client.request_sync('textDocument/hover', at(7, 5), 10000, buf)
  say('hover G71 ' .. span(hover.result.range) .. ': ' .. hover.result.contents.value:match('[^\n]+'))

  local def = client.request_sync('textDocument/definition', at(12, 11), 10000, buf)
  local loc = def.result[1] or def.result
  say('definition p2000: ' .. tail(loc.uri) .. ' ' .. span(loc.range))

  -- Formatting through Neovim's own edit application: the buffer changes.
  vim.lsp.buf.formatting_sync(nil, 10000)
  say('after formatting, line 12: ' .. vim.api.nvim_buf_get_lines(buf, 12, 13, false)[1])
  say('buffer modified: ' .. tostring(vim.bo[buf].modified))

  -- The edit went to the server as an incremental change: its hover sees the new text.
  local hover2 = client.request_sync('textDocument/hover', at(12, 6), 10000, buf)
  say('hover M98 after formatting: ' .. hover2.result.contents.value:match('[^\n]+'))

  client.stop()
  if not vim.wait(10000, function() return exit_code ~= nil end, 50) then return fail('the server did not exit') end
  say('exit code ' .. exit_code)
end)
if not ok then fail(tostring(err)) else finish(0) end
