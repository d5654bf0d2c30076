-- kerf for Neovim (0.7 and later): starts `kerf lsp` for G-code buffers through Neovim's own LSP
-- client, one server per project root (the folder of the nearest .kerf.toml or .git, else the
-- file's folder), and passes the kerf settings (dialect, machine, language, baseline).
--
--   require('kerf').setup({ cmd = { 'kerf', 'lsp' }, dialect = 'auto', language = 'en' })
local M = {}

M.config = {
  cmd = { 'kerf', 'lsp' },
  dialect = 'auto',    -- or 'fanuc-lathe-a' ... (`kerf dialects`)
  machine = '',        -- a machine file (machine/SCHEMA.md)
  language = 'en',     -- hover texts: 'en' or 'ru'
  baseline = '',       -- a baseline of `kerf check --write-baseline`
  on_attach = nil,     -- function(client, bufnr), e.g. to map keys
  handlers = nil,      -- extra LSP handlers
}

-- File names of NC programs: the usual extensions and the O-number names of controls.
M.patterns = { '*.nc', '*.NC', '*.ngc', '*.NGC', '*.tap', '*.TAP', '*.cnc', '*.CNC', '*.mpf', '*.MPF', '*.eia', '*.EIA',
               'O[0-9][0-9][0-9][0-9]', 'O[0-9][0-9][0-9][0-9][0-9]' }

local clients = {}   -- root → client id

local function settings()
  local c = M.config
  return { dialect = c.dialect, machine = c.machine, language = c.language, baseline = c.baseline }
end

local function root_dir(bufnr)
  local file = vim.api.nvim_buf_get_name(bufnr)
  local dir = vim.fn.fnamemodify(file, ':p:h')
  local found = vim.fn.findfile('.kerf.toml', dir .. ';')
  if found ~= '' then return vim.fn.fnamemodify(found, ':p:h') end
  local git = vim.fn.finddir('.git', dir .. ';')
  if git ~= '' then return vim.fn.fnamemodify(git, ':p:h:h') end
  return dir
end

function M.attach(bufnr)
  local root = root_dir(bufnr)
  local id = clients[root]
  if not id or not vim.lsp.get_client_by_id(id) then
    id = vim.lsp.start_client({
      name = 'kerf',
      cmd = M.config.cmd,
      root_dir = root,
      workspace_folders = { { uri = vim.uri_from_fname(root), name = root } },
      init_options = settings(),
      settings = { kerf = settings() },   -- answers the server's workspace/configuration
      on_attach = M.config.on_attach,
      handlers = M.config.handlers,
    })
    clients[root] = id
  end
  if id then vim.lsp.buf_attach_client(bufnr, id) end
end

function M.setup(opts)
  M.config = vim.tbl_extend('force', M.config, opts or {})
  local group = vim.api.nvim_create_augroup('kerf', { clear = true })
  vim.api.nvim_create_autocmd({ 'BufRead', 'BufNewFile' }, {
    group = group,
    pattern = M.patterns,
    callback = function(args) vim.api.nvim_buf_set_option(args.buf, 'filetype', 'gcode') end,
  })
  vim.api.nvim_create_autocmd('FileType', {
    group = group,
    pattern = 'gcode',
    callback = function(args) M.attach(args.buf) end,
  })
end

return M
